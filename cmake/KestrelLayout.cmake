# The install layout, relative to the install prefix, and the RPATHs that make an install
# relocatable: every installed binary finds kestrel's libraries through a path relative to its own
# folder ($ORIGIN), so a prefix can be moved, copied or unpacked anywhere and still run without
# LD_LIBRARY_PATH.
#
#   <prefix>/bin/kestrel                       RPATH $ORIGIN/../lib
#   <prefix>/lib/libkestrel*.so.*              RPATH $ORIGIN
#   <prefix>/lib/kestrel/plugins/kestrel_*.so  RPATH $ORIGIN/../..
#   <prefix>/lib/cmake/kestrel/                the CMake package
#   <prefix>/include/kestrel/                  the plugin-facing headers
#   <prefix>/share/kestrel/{graphs,examples,docs}
#
# (lib is CMAKE_INSTALL_LIBDIR, which may be lib/<multiarch> with a /usr prefix; the RPATHs follow.)
set(KESTREL_INSTALL_PLUGINDIR "${CMAKE_INSTALL_LIBDIR}/kestrel/plugins")
set(KESTREL_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/kestrel")
set(KESTREL_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/kestrel")

# kestrel_origin_rpath(VAR FOLDER): the RPATH entry that leads from an installed binary in FOLDER
# (relative to the prefix) to kestrel's library folder. An absolute folder cannot be relocated;
# it gets the absolute library folder.
function(kestrel_origin_rpath var folder)
  if(IS_ABSOLUTE "${folder}" OR IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
    set(${var} "${CMAKE_INSTALL_FULL_LIBDIR}" PARENT_SCOPE)
    return()
  endif()
  file(RELATIVE_PATH rel "/prefix/${folder}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
  string(REGEX REPLACE "/+$" "" rel "${rel}")
  if(rel STREQUAL "")
    set(${var} "$ORIGIN" PARENT_SCOPE)
  else()
    set(${var} "$ORIGIN/${rel}" PARENT_SCOPE)
  endif()
endfunction()

# Executables by default (CMAKE_INSTALL_RPATH initialises every target's INSTALL_RPATH);
# KestrelInstall.cmake sets the libraries', kestrel_add_plugin() the plugins'.
kestrel_origin_rpath(CMAKE_INSTALL_RPATH "${CMAKE_INSTALL_BINDIR}")
kestrel_origin_rpath(KESTREL_LIBRARY_RPATH "${CMAKE_INSTALL_LIBDIR}")
kestrel_origin_rpath(KESTREL_PLUGIN_RPATH "${KESTREL_INSTALL_PLUGINDIR}")
