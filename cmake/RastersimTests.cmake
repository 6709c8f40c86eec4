# Every test of the suite runs with TMPDIR set to one folder of its own, RASTERSIM_TEST_TMPDIR. The
# fixture suite_temporary_folder empties it before the first test and requires it empty after the
# last (suite.temporary_folder_left_clean names what is left): a test that leaves a file outside its
# own temporary folder fails the suite. The folder is outside the checkout (the install tests need a
# prefix outside it) and one per build folder; two ctest runs on one build folder at once share it.
if(DEFINED ENV{TMPDIR} AND IS_DIRECTORY "$ENV{TMPDIR}")
  set(rastersim_system_tmpdir "$ENV{TMPDIR}")
else()
  set(rastersim_system_tmpdir /tmp)
endif()
string(MD5 rastersim_build_hash "${PROJECT_BINARY_DIR}")
string(SUBSTRING "${rastersim_build_hash}" 0 12 rastersim_build_hash)
set(RASTERSIM_TEST_TMPDIR "${rastersim_system_tmpdir}/rastersim-tests-${rastersim_build_hash}" CACHE PATH
    "The suite's temporary folder (TMPDIR of every test), emptied before and checked empty after the suite")
# For gtest_discover_tests(... PROPERTIES ${RASTERSIM_TEST_PROPERTIES} ...).
set(RASTERSIM_TEST_PROPERTIES ENVIRONMENT TMPDIR=${RASTERSIM_TEST_TMPDIR} FIXTURES_REQUIRED suite_temporary_folder)

if(RASTERSIM_TESTS)
  add_test(NAME suite.temporary_folder_prepared
           COMMAND ${CMAKE_COMMAND} -D DIR=${RASTERSIM_TEST_TMPDIR} -D MODE=prepare -P ${CMAKE_CURRENT_LIST_DIR}/temporary_folder.cmake)
  add_test(NAME suite.temporary_folder_left_clean
           COMMAND ${CMAKE_COMMAND} -D DIR=${RASTERSIM_TEST_TMPDIR} -D MODE=check -P ${CMAKE_CURRENT_LIST_DIR}/temporary_folder.cmake)
  set_tests_properties(suite.temporary_folder_prepared PROPERTIES FIXTURES_SETUP suite_temporary_folder LABELS suite)
  set_tests_properties(suite.temporary_folder_left_clean PROPERTIES FIXTURES_CLEANUP suite_temporary_folder LABELS suite)
endif()

# Called once in each CMakeLists.txt that adds tests with add_test: at the end of that folder, its
# tests get the suite's TMPDIR and the fixture (set_property(TEST) reaches only the current folder).
function(rastersim_isolate_tests)
  cmake_language(DEFER CALL _rastersim_isolate_folder_tests)
endfunction()

function(_rastersim_isolate_folder_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  list(REMOVE_ITEM tests suite.temporary_folder_prepared suite.temporary_folder_left_clean)
  if(tests)
    set_property(TEST ${tests} APPEND PROPERTY ENVIRONMENT TMPDIR=${RASTERSIM_TEST_TMPDIR})
    set_property(TEST ${tests} APPEND PROPERTY FIXTURES_REQUIRED suite_temporary_folder)
  endif()
endfunction()
