# A Debian package of the program and its assets: `cpack -G DEB` in the build folder writes
# rattleback_<version>_<arch>.deb. Installs /usr/bin/rattleback and /usr/share/rattleback/.
set(RATTLEBACK_MAINTAINER "rattleback maintainers <maintainers@users.noreply.h-seed-88b4351e.example>"
    CACHE STRING "The package's Maintainer field: Name <email>")
set(RATTLEBACK_HOMEPAGE "" CACHE STRING "The package's Homepage field (left out when empty)")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME rattleback)
set(CPACK_PACKAGE_VENDOR "rattleback maintainers")
set(CPACK_PACKAGE_CONTACT "${RATTLEBACK_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "rattleback (celt) simulator with headless video rendering")
set(CPACK_PACKAGE_DESCRIPTION
    "Simulates the rattleback (celt), the toy that, spun the wrong way, rocks, stops and
spins back. YAML scene files in; MP4 videos (H.264), PNG stills, CSV telemetry, plots
(gnuplot) and a report of the body's mass properties and linear stability out.
It renders headlessly through EGL (Mesa's llvmpipe, or a GPU) or OSMesa: no display or
GPU needed.")
if(RATTLEBACK_HOMEPAGE)
  set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${RATTLEBACK_HOMEPAGE}")
endif()
set(CPACK_STRIP_FILES ON)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Shared libraries (libEGL, FFmpeg, libpng, FreeType, yaml-cpp, libstdc++) through
# dpkg-shlibdeps (package dpkg-dev). Opened at run time, so named here: the font; Mesa's EGL
# vendor library (libglvnd's libEGL finds it, and llvmpipe behind it, through its JSON file);
# HDF5 (libhdf5_serial.so.103, opened when a .h5 is written: tasks/hdf5.cpp).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core, libegl-mesa0, libhdf5-103-1")
# `simulate --plot` and sweeps' heatmaps run gnuplot; OSMesa (dlopen) is the second backend;
# the Python package (lib/python3/dist-packages/rattleback) imports NumPy.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gnuplot-nox, libosmesa6, python3-numpy")
# Without dpkg-shlibdeps CPack would quietly write a package without its library Depends.
set(CPACK_PROJECT_CONFIG_FILE "${CMAKE_CURRENT_LIST_DIR}/cpack_checks.cmake")

include(CPack)
