# Read by cpack for each generator (CPACK_PROJECT_CONFIG_FILE): refuse to write a .deb whose
# Depends would miss the shared libraries because dpkg-shlibdeps is absent.
if(CPACK_GENERATOR STREQUAL "DEB")
  find_program(RATTLEBACK_DPKG_SHLIBDEPS dpkg-shlibdeps)
  if(NOT RATTLEBACK_DPKG_SHLIBDEPS)
    message(FATAL_ERROR "dpkg-shlibdeps not found: install dpkg-dev (it fills the package's Depends)")
  endif()
endif()
