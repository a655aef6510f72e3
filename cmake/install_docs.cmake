# Installs the documentation's pages with the docs site's includes written out: a line
# `--8<-- "examples/weighted_body.py"` (pymdownx.snippets, mkdocs.yml) becomes the file's text,
# so that a page read from the installed folder shows the script, not the include.
# Set before it runs (CMakeLists.txt's install(CODE)): RB_SOURCE, RB_DOCDIR (relative to the
# prefix, or absolute), RB_STAGING (a folder of the build for the written-out pages).
file(GLOB pages "${RB_SOURCE}/docs/*.md")
file(MAKE_DIRECTORY "${RB_STAGING}")
set(written)
foreach(page IN LISTS pages)
  file(READ "${page}" text)
  string(REGEX MATCHALL "--8<-- \"[^\"\n]+\"" includes "${text}")
  foreach(include IN LISTS includes)
    string(REGEX REPLACE "^--8<-- \"([^\"]+)\"$" "\\1" path "${include}")
    if(NOT EXISTS "${RB_SOURCE}/${path}")
      message(FATAL_ERROR "${page}: includes ${path}, which is not in the source")
    endif()
    file(READ "${RB_SOURCE}/${path}" body)
    string(REGEX REPLACE "\n$" "" body "${body}")
    string(REPLACE "${include}" "${body}" text "${text}")
  endforeach()
  get_filename_component(name "${page}" NAME)
  file(WRITE "${RB_STAGING}/${name}" "${text}")
  list(APPEND written "${RB_STAGING}/${name}")
endforeach()
# file(INSTALL) honours DESTDIR (the .deb's staging) and lists the pages in the manifest.
if(IS_ABSOLUTE "${RB_DOCDIR}")
  set(destination "${RB_DOCDIR}")
else()
  set(destination "${CMAKE_INSTALL_PREFIX}/${RB_DOCDIR}")
endif()
file(INSTALL ${written} DESTINATION "${destination}")
