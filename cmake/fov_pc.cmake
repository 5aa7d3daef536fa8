# Writes fov.pc at install time (CMakeLists.txt's install(CODE)), so that the prefix is the one
# given to `cmake --install --prefix` and not the one configured. In: FOV_PC_TEMPLATE,
# FOV_PC_OUT, FOV_PC_VERSION, FOV_PC_INCDIR (relative to the prefix, or absolute).
set(FOV_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
if(IS_ABSOLUTE "${FOV_PC_INCDIR}")
    set(FOV_PC_INCLUDEDIR "${FOV_PC_INCDIR}")
else()
    set(FOV_PC_INCLUDEDIR "\${prefix}/${FOV_PC_INCDIR}")
endif()
configure_file("${FOV_PC_TEMPLATE}" "${FOV_PC_OUT}" @ONLY)
