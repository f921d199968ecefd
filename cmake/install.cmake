# cmake --install: the libraries ivv::scene, ivv::closed_forms, ivv::solver, ivv::oracles,
# ivv::conformance, the headers they
# need, the find_package(ivv) files, and the shipped data. Installed layout under <prefix>:
#   include/ivv/{scene,closed_forms,solver,oracles,verification}/...   (#include "solver/laws/law.h", as in the tree)
#   lib/libivv_*.a, lib/cmake/ivv/ivvConfig.cmake, ivvConfigVersion.cmake, ivvTargets.cmake
#   share/ivv/*.csv, *.md, generate_*.py, scenes/*.toml   (scene/data_dir.h finds them)
#   include/ivv/examples/laws/*.h, share/ivv/examples/laws/ (the example laws, and a CMake
#   project that checks one: copy it for a law of your own)
# Components: ivv_development (libraries, headers, CMake files) and ivv_data; the ivv program
# (app/) installs as the default component.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(IVV_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/ivv)
set(IVV_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/ivv)

# The build tree mirrors the installed data layout: every program of the build tree
# (<build>/<dir>/<exe>) finds the data at <exe>/../share/ivv, as an installed one does.
file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/share)
file(CREATE_LINK ${PROJECT_SOURCE_DIR}/reference_data ${PROJECT_BINARY_DIR}/share/ivv SYMBOLIC)

set_target_properties(ivv_scene PROPERTIES EXPORT_NAME scene)
set_target_properties(ivv_closed_forms PROPERTIES EXPORT_NAME closed_forms)
# An instrumented build (the asan preset's -fsanitize=address,undefined in CMAKE_CXX_FLAGS)
# installs instrumented objects: whoever links them needs the sanitizer runtimes, so the
# installed targets carry the same -fsanitize= as a link option (without it `make asan`'s
# downstream project failed with "undefined reference to __asan_init"). fuzzer-no-link is a
# compile-only instrumentation and is not passed on.
string(REGEX MATCHALL "-fsanitize=[^ ]+" ivv_sanitize_flags "${CMAKE_CXX_FLAGS}")
foreach(flag IN LISTS ivv_sanitize_flags)
  string(REPLACE "fuzzer-no-link," "" flag "${flag}")
  string(REPLACE ",fuzzer-no-link" "" flag "${flag}")
  if(NOT flag STREQUAL "-fsanitize=fuzzer-no-link")
    target_link_options(ivv_scene INTERFACE ${flag})
  endif()
endforeach()

set_target_properties(ivv_solver PROPERTIES EXPORT_NAME solver)
set_target_properties(ivv_oracles PROPERTIES EXPORT_NAME oracles)
set_target_properties(ivv_conformance PROPERTIES EXPORT_NAME conformance)
install(TARGETS ivv_scene ivv_closed_forms ivv_solver ivv_oracles ivv_conformance EXPORT ivvTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ivv_development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ivv_development
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT ivv_development)
install(EXPORT ivvTargets NAMESPACE ivv:: DESTINATION ${IVV_INSTALL_CMAKEDIR}
        COMPONENT ivv_development)

# Headers: all of solver/ and oracles/; of verification/ the conformance checks and what they
# include (the battery, registry and report stay in the tree).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scene ${PROJECT_SOURCE_DIR}/closed_forms
                  ${PROJECT_SOURCE_DIR}/solver ${PROJECT_SOURCE_DIR}/oracles
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ivv COMPONENT ivv_development
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_SOURCE_DIR}/verification/conformance.h
              ${PROJECT_SOURCE_DIR}/verification/check_law_request.h
              ${PROJECT_SOURCE_DIR}/verification/conformance_law.h
              ${PROJECT_SOURCE_DIR}/verification/conformance_plate_law.h
              ${PROJECT_SOURCE_DIR}/verification/conformance_gtest.h
              ${PROJECT_SOURCE_DIR}/verification/continuity_scan.h
              ${PROJECT_SOURCE_DIR}/verification/plot_data.h
              ${PROJECT_SOURCE_DIR}/verification/tolerances.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ivv/verification COMPONENT ivv_development)

# The example laws: their headers beside ivv's (#include "examples/laws/thornton.h"), and the
# directory itself, with a CMake project a user can copy, in share/ivv/examples/laws.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/laws
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ivv/examples COMPONENT ivv_development
        FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/laws
        DESTINATION ${IVV_INSTALL_DATADIR}/examples COMPONENT ivv_development)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/reference_data/ DESTINATION ${IVV_INSTALL_DATADIR}
        COMPONENT ivv_data FILES_MATCHING PATTERN "*.csv" PATTERN "*.md" PATTERN "*.py" PATTERN "*.toml")

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ivvConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ivvConfig.cmake
                              INSTALL_DESTINATION ${IVV_INSTALL_CMAKEDIR}
                              PATH_VARS IVV_INSTALL_DATADIR)
# 0.x: a minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ivvConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ivvConfig.cmake ${PROJECT_BINARY_DIR}/ivvConfigVersion.cmake
        DESTINATION ${IVV_INSTALL_CMAKEDIR} COMPONENT ivv_development)

# ivv added to another project (add_subdirectory, FetchContent): that project's programs find
# the data in this source tree, as a program built against an installation finds share/ivv.
if(NOT PROJECT_IS_TOP_LEVEL)
  target_compile_definitions(ivv_scene INTERFACE
    "$<BUILD_INTERFACE:IVV_PACKAGE_DATA_DIR=\"${PROJECT_SOURCE_DIR}/reference_data\">")
endif()
