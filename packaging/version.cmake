# Writes raystudio_version.h: the project version plus the git commit of the checkout.
# Run at every build (cmake -P) so a new commit shows without reconfiguring; configure_file
# leaves the header untouched when nothing changed, so nothing recompiles then.
# In: SOURCE_DIR, OUTPUT, PROJECT_VERSION.
set(RAYSTUDIO_GIT_COMMIT "")
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse --short HEAD
    OUTPUT_VARIABLE RAYSTUDIO_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE git_result ERROR_QUIET)
  if(NOT git_result EQUAL 0)
    set(RAYSTUDIO_GIT_COMMIT "")
  else()
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} diff --quiet HEAD --
      RESULT_VARIABLE dirty ERROR_QUIET)
    if(NOT dirty EQUAL 0)
      string(APPEND RAYSTUDIO_GIT_COMMIT "-dirty")
    endif()
  endif()
endif()
if(RAYSTUDIO_GIT_COMMIT)
  set(RAYSTUDIO_VERSION_STRING "${PROJECT_VERSION} (git ${RAYSTUDIO_GIT_COMMIT})")
else()
  set(RAYSTUDIO_VERSION_STRING "${PROJECT_VERSION}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.h.in ${OUTPUT} @ONLY)
