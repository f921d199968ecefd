# cmake -P script behind the ctest `downstream_package`: every step must succeed.
#   1. build the three libraries (a no-op after `make`), 2. cmake --install them, their headers,
#   config files and data into WORK_DIR/prefix (a fresh directory), 3. configure
#   examples/downstream/ with only that prefix to find ivv by, 4. build it, 5. run its program
#   on the paper scene and on a shipped scene by name (the installed data, IVV_DATA_DIR unset), 6. run its
#   conformance tests (one ctest test: the battery once), 7. copy the installed examples/laws/,
#   build it and run its check.
foreach(var IVV_SOURCE_DIR IVV_BINARY_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT ${var})
    message(FATAL_ERROR "downstream test: ${var} not given")
  endif()
endforeach()

function(step name)
  message(STATUS "downstream test: ${name}: ${ARGN}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=IVV_DATA_DIR ${ARGN}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "downstream test: ${name} failed (${rc})")
  endif()
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${prefix})
file(MAKE_DIRECTORY ${WORK_DIR})

step("build the libraries" ${CMAKE_COMMAND} --build ${IVV_BINARY_DIR} -j 2
     --target ivv_solver ivv_oracles ivv_conformance)
foreach(component ivv_development ivv_data)
  step("install ${component}" ${CMAKE_COMMAND} --install ${IVV_BINARY_DIR} --prefix ${prefix}
       --component ${component})
endforeach()

# The downstream project is compiled as ivv was (CXX_FLAGS: the preset's warnings and, for
# asan, its sanitizers); the installed targets also carry the sanitizer link options.
if(NOT CXX_FLAGS)
  set(CXX_FLAGS "-Wall -Wextra -Wpedantic")
endif()
set(configure_args -S ${IVV_SOURCE_DIR}/examples/downstream -B ${build} -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}")
if(CXX_COMPILER_LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_COMPILER_LAUNCHER})
endif()
step("configure examples/downstream" ${CMAKE_COMMAND} ${configure_args})
# ivv must come from the prefix just installed, not from anywhere else on the machine.
file(STRINGS ${build}/CMakeCache.txt ivv_dir REGEX "^ivv_DIR:")
if(NOT ivv_dir STREQUAL "ivv_DIR:PATH=${prefix}/lib/cmake/ivv")
  message(FATAL_ERROR "downstream test: found ivv at '${ivv_dir}', not in ${prefix}")
endif()
step("build examples/downstream" ${CMAKE_COMMAND} --build ${build} -j 2)
step("run restitution" ${build}/restitution)
# A shipped scene by name: found in the installation's share/ivv (IVV_PACKAGE_DATA_DIR).
step("run restitution on an installed scene" ${build}/restitution steel-on-aluminium)
step("run the conformance suite" ${CMAKE_CTEST_COMMAND} --test-dir ${build} -j 2
     --output-on-failure)

# 7. the installed example laws: copy share/ivv/examples/laws as a user would, configure, build
#    and run it (Thornton's law through every conformance check).
set(laws_copy ${WORK_DIR}/my-law)
file(REMOVE_RECURSE ${laws_copy})
file(COPY ${prefix}/share/ivv/examples/laws/ DESTINATION ${laws_copy})
list(TRANSFORM configure_args REPLACE "^${IVV_SOURCE_DIR}/examples/downstream$" "${laws_copy}")
list(TRANSFORM configure_args REPLACE "^${build}$" "${WORK_DIR}/build-my-law")
step("configure the installed examples/laws" ${CMAKE_COMMAND} ${configure_args})
step("build the installed examples/laws" ${CMAKE_COMMAND} --build ${WORK_DIR}/build-my-law -j 2)
step("run check_thornton" ${WORK_DIR}/build-my-law/check_thornton)
