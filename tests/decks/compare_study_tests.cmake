# End-to-end tests of `inpact compare` and `inpact study` (tests/decks/compare_study.cmake), each
# in its own scratch folder under the build tree.
set(compare_study_runner ${CMAKE_CURRENT_LIST_DIR}/compare_study.cmake)
foreach(mode compare_rerun compare_changed_load compare_renumbered compare_incomplete
             study_resume study_failed_case study_gnu_parallel study_fork_matches_exec)
  add_test(NAME decks.${mode}
           COMMAND ${CMAKE_COMMAND} -DINPACT=$<TARGET_FILE:inpact> -DSOURCE=${PROJECT_SOURCE_DIR}
                   -DWORK=${CMAKE_CURRENT_BINARY_DIR}/compare_study/${mode} -DMODE=${mode} -P ${compare_study_runner})
  set_tests_properties(decks.${mode} PROPERTIES LABELS "decks;compare_study" TIMEOUT 300)
endforeach()
set_tests_properties(decks.study_gnu_parallel PROPERTIES SKIP_REGULAR_EXPRESSION "GNU parallel not installed")
if(INPACT_HAVE_PETSC AND MPIEXEC_EXECUTABLE)
  add_test(NAME decks.study_ranks_per_case
           COMMAND ${CMAKE_COMMAND} -DINPACT=$<TARGET_FILE:inpact> -DSOURCE=${PROJECT_SOURCE_DIR}
                   -DWORK=${CMAKE_CURRENT_BINARY_DIR}/compare_study/study_ranks_per_case -DMODE=study_ranks_per_case
                   -P ${compare_study_runner})
  set_tests_properties(decks.study_ranks_per_case PROPERTIES LABELS "decks;compare_study;mpi" TIMEOUT 300 PROCESSORS 2)
endif()
