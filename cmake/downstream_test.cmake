# ctest `downstream_package` (label package, in `make test`): install ivv into a prefix in the
# build tree, then configure, build and run examples/downstream/ against that installation
# alone (its program and its conformance tests). See cmake/downstream_test_run.cmake.
add_test(NAME downstream_package
         COMMAND ${CMAKE_COMMAND}
                 -DIVV_SOURCE_DIR=${PROJECT_SOURCE_DIR}
                 -DIVV_BINARY_DIR=${PROJECT_BINARY_DIR}
                 -DWORK_DIR=${PROJECT_BINARY_DIR}/downstream-test
                 -DGENERATOR=${CMAKE_GENERATOR}
                 -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
                 -DCXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
                 -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
                 "-DCXX_FLAGS=${CMAKE_CXX_FLAGS}"
                 -P ${PROJECT_SOURCE_DIR}/cmake/downstream_test_run.cmake)
# Compiling the conformance headers (every integrator, the 50-digit reference) dominates.
set_tests_properties(downstream_package PROPERTIES LABELS package TIMEOUT 900 PROCESSORS 2)
