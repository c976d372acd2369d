# include()d by CLI test scripts that need a user who cannot write everywhere: when the tests
# run as root (root writes anywhere) it sets `as_user` to a setpriv prefix that runs a command as
# the user nobody, and gives nobody the folders named; otherwise `as_user` is empty. A macro, so
# its return() skips the rest of the calling script (with a warning) where nobody cannot run.
#   proxygi_as_nobody(<what the check is, for the warning> [<folder nobody must own>...])
macro(proxygi_as_nobody what)
  set(as_user "")
  execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(uid STREQUAL "0")
    find_program(SETPRIV setpriv)
    if(NOT SETPRIV)
      message(WARNING "${what} skipped: running as root without setpriv to drop to nobody")
      return()
    endif()
    set(as_user ${SETPRIV} --reuid=65534 --regid=65534 --clear-groups)
    execute_process(COMMAND ${as_user} ${PROXYGI} --version RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
    if(NOT code EQUAL 0)
      message(WARNING "${what} skipped: the user nobody cannot run ${PROXYGI} (a folder above it is private)")
      return()
    endif()
    if(NOT "${ARGN}" STREQUAL "")
      execute_process(COMMAND chown -R 65534:65534 ${ARGN})
      # Running the binary is not enough: a private folder above these (mktemp -d makes 0700
      # ones) still keeps nobody out of them, so each must be writable as nobody.
      foreach(folder ${ARGN})
        execute_process(COMMAND ${as_user} test -w ${folder} RESULT_VARIABLE code)
        if(NOT code EQUAL 0)
          message(WARNING "${what} skipped: the user nobody cannot write ${folder} (a folder above it is private)")
          return()
        endif()
      endforeach()
    endif()
  endif()
endmacro()
