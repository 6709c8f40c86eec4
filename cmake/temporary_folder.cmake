# cmake -D DIR=FOLDER -D MODE=prepare|check -P temporary_folder.cmake (cmake/RastersimTests.cmake):
cmake_policy(SET CMP0009 NEW)  # GLOB_RECURSE lists a link without following it
# prepare empties FOLDER; check fails naming every file or folder a test left in it.
if(MODE STREQUAL "prepare")
  file(REMOVE_RECURSE "${DIR}")
  file(MAKE_DIRECTORY "${DIR}")
elseif(MODE STREQUAL "check")
  if(NOT IS_DIRECTORY "${DIR}")
    message(FATAL_ERROR "the suite's temporary folder ${DIR} is gone: a test removed it")
  endif()
  file(GLOB_RECURSE left LIST_DIRECTORIES true RELATIVE "${DIR}" "${DIR}/*")
  # GLOB's * matches hidden names too.
  if(left)
    list(SORT left)
    list(LENGTH left count)
    list(JOIN left "\n  " shown)
    message(FATAL_ERROR "${count} files or folders were left in the suite's temporary folder ${DIR} "
                        "(a test must remove what it makes in TMPDIR):\n  ${shown}")
  endif()
  message(STATUS "the suite's temporary folder ${DIR} is empty")
else()
  message(FATAL_ERROR "MODE must be prepare or check, not '${MODE}'")
endif()
