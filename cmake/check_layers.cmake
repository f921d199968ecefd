# The layer rule of docs/design.md §4, checked on the source tree (a ctest entry: layers_test):
#
#   scene < closed_forms < solver < oracles < validation < verification < reports < app < python
#
# A file in one layer may include headers of its own layer and of the layers below it, never of
# a layer above. bench/ and fuzz/ are leaves: no library includes them; only the command line
# (app/, for `ivv bench`) may. python/ (the module `import ivv`) is the top layer: it may use
# every library, and nothing includes it. Tests (*_test.cc) sit beside the unit they check and
# may use any layer to check it.
#
# Usage: cmake -DSOURCE_DIR=<tree> -P check_layers.cmake   (fails listing every violation)
set(layers scene closed_forms solver oracles validation verification reports app python)
set(leaves bench fuzz)

set(violations "")
foreach(dir IN LISTS layers leaves)
  list(FIND layers ${dir} rank)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${dir}/*.h ${SOURCE_DIR}/${dir}/*.cc)
  foreach(file IN LISTS files)
    if(file MATCHES "_test\\.cc$")
      continue()
    endif()
    file(STRINGS ${file} includes REGEX "^#include \"[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" target "${line}")
      if(target STREQUAL dir)
        continue()
      endif()
      list(FIND layers ${target} target_rank)
      list(FIND leaves ${target} target_leaf)
      file(RELATIVE_PATH where ${SOURCE_DIR} ${file})
      if(target_leaf GREATER -1 AND NOT dir STREQUAL "app")
        list(APPEND violations "${where} includes the leaf ${target}/: ${line}")
      elseif(rank GREATER -1 AND target_rank GREATER rank)
        list(APPEND violations "${where} (layer ${dir}) includes a higher layer: ${line}")
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations)
  list(LENGTH violations n)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "${n} include(s) against the layers of docs/design.md §4:\n  ${text}")
endif()
message(STATUS "layers: no include runs from a lower layer to a higher one")
