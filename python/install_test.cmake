# `cmake --install` puts the Python package where the prefix's Python finds it: installs the
# component ivv_python into a fresh prefix and imports ivv from there (not from the build tree).
#
# Usage: cmake -DBUILD_DIR=<build> -DPREFIX=<dir> -DPYTHON_DIR=<relative> -DPYTHON=<python3>
#              -P install_test.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                        --component ivv_python
                RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install --component ivv_python failed: ${result}")
endif()
set(check "import ivv, os; assert os.path.dirname(ivv.__file__) == os.path.join('${PREFIX}', '${PYTHON_DIR}', 'ivv'), ivv.__file__; print('e =', ivv.simulate(ivv.scene('paper', v0=1, zeta=0.1)).e)")
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${PREFIX}/${PYTHON_DIR}
                        ${PYTHON} -c "${check}"
                WORKING_DIRECTORY ${PREFIX}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the installed module does not import: ${out}${err}")
endif()
message(STATUS "installed module: ${out}")
