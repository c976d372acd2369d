# Warnings for the project's own code only: third-party headers come in as SYSTEM includes.
add_library(proxygi_warnings INTERFACE)
target_compile_options(proxygi_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual
  -Wimplicit-fallthrough
  # Vulkan structs are written VkX x{VK_STRUCTURE_TYPE_X}: the rest is value-initialized on purpose.
  -Wno-missing-field-initializers)
if(PROXYGI_WERROR)
  target_compile_options(proxygi_warnings INTERFACE -Werror)
endif()

# proxygi_library(NAME SOURCES ... [DEPS ...]): one static library per folder, public include
# root at the repository top so headers are included as "anim/clip.h", "sh/basis.h", ...
function(proxygi_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(proxygi_${name} STATIC ${ARG_SOURCES})
  add_library(proxygi::${name} ALIAS proxygi_${name})
  target_include_directories(proxygi_${name} PUBLIC ${PROJECT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(proxygi_${name} PUBLIC ${ARG_DEPS} PRIVATE proxygi_warnings ${ARG_PRIVATE_DEPS})
endfunction()
