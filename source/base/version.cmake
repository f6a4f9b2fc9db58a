# Writes contact_version.h with the commit of the source tree where it is a
# git checkout ("unknown" elsewhere, e.g. an unpacked archive), and "+" for
# uncommitted changes. Run at every build (CMakeLists.txt, target
# contact_version); the header is rewritten only when its text changes, so
# an unchanged commit recompiles nothing.
set(COMMIT "unknown")
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS "${SOURCE_DIR}/.git")
  # The commit itself (a tag would make 'describe' print its name).
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR}
    rev-parse --short=12 HEAD
    OUTPUT_VARIABLE COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE GIT_RESULT ERROR_QUIET)
  if(NOT GIT_RESULT EQUAL 0)
    set(COMMIT "unknown")
  else()
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR}
      diff --quiet HEAD RESULT_VARIABLE DIRTY ERROR_QUIET)
    if(NOT DIRTY EQUAL 0)
      set(COMMIT "${COMMIT}+")
    endif()
  endif()
endif()
# Written only when its text changes: the tests build in parallel, and
# each build runs this script (a rewrite of the same text, or a temporary
# file, would race with a compiler reading the header).
set(TEXT "#define CONTACT_VERSION \"${VERSION}\"\n#define CONTACT_COMMIT \"${COMMIT}\"\n")
set(OLD_TEXT "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} OLD_TEXT)
endif()
if(NOT OLD_TEXT STREQUAL TEXT)
  file(WRITE ${OUTPUT} "${TEXT}")
endif()
