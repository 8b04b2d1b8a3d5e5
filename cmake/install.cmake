# `cmake --install`: the phongvk command, libphongvk.so (every library and the embedded SPIR-V in
# one shared object), the public headers, a CMake package (find_package(phongvk CONFIG): the
# target phongvk::phongvk, with a version file) and a pkg-config file (phongvk.pc).
include(CMakePackageConfigHelpers)

set(PHONGVK_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/phongvk)
install(TARGETS phongvk_shared EXPORT phongvkTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS phongvk RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/phongvk DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT phongvkTargets NAMESPACE phongvk:: DESTINATION ${PHONGVK_CMAKE_DIR})
configure_package_config_file(cmake/phongvkConfig.cmake.in ${PROJECT_BINARY_DIR}/phongvkConfig.cmake
                              INSTALL_DESTINATION ${PHONGVK_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/phongvkConfigVersion.cmake COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/phongvkConfig.cmake ${PROJECT_BINARY_DIR}/phongvkConfigVersion.cmake
        DESTINATION ${PHONGVK_CMAKE_DIR})
# Relocatable: the prefix is found from the .pc file's own folder, so `cmake --install --prefix`
# anywhere gives a working file.
file(RELATIVE_PATH PHONGVK_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
configure_file(cmake/phongvk.pc.in ${PROJECT_BINARY_DIR}/phongvk.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/phongvk.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
