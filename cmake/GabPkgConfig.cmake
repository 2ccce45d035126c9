# gab.pc for pkg-config, from cmake/gab.pc.in. Written at install time, not at
# configure time: the prefix is known only then (cmake --install build
# --prefix P), and the file holds it.
#
# Libs carries -Wl,-rpath to the prefix's libdir: `cc app.c $(pkg-config
# --libs gab)` against ~/.local must give a program that runs without
# LD_LIBRARY_PATH, and the loader does not search a prefix it was not told
# of. A libdir the loader searches anyway (/usr/lib, ...: CMake's own list of
# system directories, where it adds no rpath either) gets none.
# Libs.private is what the static libgab needs besides (pkg-config --static):
# tinyobjloader (the mesh layer's OBJ reader), the C++ runtime, threads.
#
# Needs GAB_CXX_RUNTIME (CMakeLists.txt).
set(gab_pc_cxx_runtime "")
foreach(library ${GAB_CXX_RUNTIME})
  string(APPEND gab_pc_cxx_runtime " -l${library}")
endforeach()
string(STRIP "${gab_pc_cxx_runtime}" gab_pc_cxx_runtime)

set(gab_system_lib_dirs ${CMAKE_PLATFORM_IMPLICIT_LINK_DIRECTORIES} ${CMAKE_C_IMPLICIT_LINK_DIRECTORIES})
install(CODE "
  set(gab_system_lib_dirs \"${gab_system_lib_dirs}\")
  set(GAB_PC_PREFIX \"\${CMAKE_INSTALL_PREFIX}\")
  set(GAB_PC_RPATH \" -Wl,-rpath,\\\${libdir}\")
  list(FIND gab_system_lib_dirs \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}\" gab_pc_system)
  if(gab_pc_system GREATER -1)
    set(GAB_PC_RPATH \"\")
  endif()
  set(CMAKE_INSTALL_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
  set(CMAKE_INSTALL_INCLUDEDIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
  set(PROJECT_VERSION \"${PROJECT_VERSION}\")
  set(GAB_PC_CXX_RUNTIME \"${gab_pc_cxx_runtime}\")
  configure_file(\"${CMAKE_CURRENT_LIST_DIR}/gab.pc.in\" \"${PROJECT_BINARY_DIR}/gab.pc\" @ONLY)
")
install(FILES ${PROJECT_BINARY_DIR}/gab.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
