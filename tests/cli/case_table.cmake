# include()d by CLI test scripts with a table of cases written "label|expected|arg~arg~...":
# splits one entry into its label, its expected text (a path or a regex, as the script uses it)
# and its argument list (the ~-separated words as a CMake list). The entry is passed by variable
# name, so a regex's escapes reach the caller as written.
#   proxygi_split_case(<entry var> <label var> <expected var> <args var>)
macro(proxygi_split_case entry_var label_var expected_var args_var)
  string(REPLACE "|" ";" _case_fields "${${entry_var}}")
  list(GET _case_fields 0 ${label_var})
  list(GET _case_fields 1 ${expected_var})
  list(GET _case_fields 2 ${args_var})
  string(REPLACE "~" ";" ${args_var} "${${args_var}}")
endmacro()
