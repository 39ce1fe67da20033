# End-to-end tests of `inpact compare` and `inpact study` with real runs of a small contact deck
# (decks/contact/patch_2d_penalty.inp, made a study deck by a *PARAMETER for its pressure).
#
#   cmake -DINPACT=path/to/inpact -DSOURCE=repo -DWORK=scratch-folder -DMODE=<mode> -P compare_study.cmake
#
# MODE: compare_rerun | compare_changed_load | compare_renumbered | compare_incomplete |
#       study_resume | study_failed_case | study_gnu_parallel | study_fork_matches_exec |
#       study_ranks_per_case
cmake_minimum_required(VERSION 3.22)
foreach(var INPACT SOURCE WORK MODE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compare_study.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(READ "${SOURCE}/decks/contact/patch_2d_penalty.inp" base)
string(REPLACE "*NODE, NSET=ALL" "*PARAMETER\nload = 10\n*NODE, NSET=ALL" deck "${base}")
string(REPLACE "TOP_S, P, 10" "TOP_S, P, <load>" deck "${deck}")
file(WRITE "${WORK}/patch.inp" "${deck}")

set(failures "")
# inpact(<expected exit> <output var> args...): runs inpact in WORK, checks the exit code.
function(inpact expected out)
  execute_process(COMMAND "${INPACT}" ${ARGN} WORKING_DIRECTORY "${WORK}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
  set(${out} "${o}${e}" PARENT_SCOPE)
  if(NOT rc STREQUAL "${expected}")
    set(failures "${failures}  inpact ${ARGN}: exit ${rc}, expected ${expected}\n${o}${e}\n" PARENT_SCOPE)
  endif()
endfunction()
function(expect_text text haystack what)
  string(FIND "${haystack}" "${text}" at)
  if(at EQUAL -1)
    set(failures "${failures}  ${what}: missing '${text}' in:\n${haystack}\n" PARENT_SCOPE)
  endif()
endfunction()

set(collect --collect max:CPRESS --collect max:-COPEN --collect sum:RF2@BOTTOM)

if(MODE STREQUAL "compare_rerun")
  # The same deck run twice compares equal, and the JSON report says so.
  inpact(0 out run patch.inp -j a -q)
  inpact(0 out run patch.inp -j b -q)
  inpact(0 out compare a.h5 b.h5 --report same.json)
  expect_text("SAME: 7 field(s) within tolerance" "${out}" "summary")
  file(READ "${WORK}/same.json" json)
  expect_text("\"same\": true" "${json}" "report")

elseif(MODE STREQUAL "compare_changed_load")
  # A changed load (-P load=12) differs; the report points at CPRESS: 10 against 12 at a slave node.
  inpact(0 out run patch.inp -j a -q)
  inpact(0 out run patch.inp -j b -q -P load=12)
  inpact(1 out compare a.h5 b.h5 --report diff.json)
  expect_text("CPRESS   DIFF" "${out}" "summary")
  expect_text("(pair SLAVE_S/MASTER_S) CPRESS: A 10 B 12" "${out}" "summary")
  expect_text("CSTATUS  ok" "${out}" "summary")
  file(READ "${WORK}/diff.json" json)
  string(JSON same GET "${json}" same)
  string(JSON field GET "${json}" fields 0 field)
  string(JSON pass GET "${json}" fields 0 pass)
  string(JSON step GET "${json}" fields 0 worst step)
  string(JSON comp GET "${json}" fields 0 worst component)
  string(JSON b GET "${json}" fields 0 worst b)
  if(NOT same STREQUAL "OFF" OR NOT field STREQUAL "CPRESS" OR pass OR NOT step STREQUAL "PRESS"
     OR NOT comp STREQUAL "CPRESS" OR b LESS 11.99 OR b GREATER 12.01)
    string(APPEND failures "  report: same=${same} field=${field} pass=${pass} step=${step} component=${comp} b=${b}\n")
  endif()
  # A tolerance file loose enough for a 20% change makes the pair pass.
  file(WRITE "${WORK}/loose.yaml" "default:\n  rtol: 0.5\nfields:\n  CPRESS:\n    rtol: 0.5\n  COPEN:\n    rtol: 0.5\n  CFN:\n    rtol: 0.5\n  RF:\n    rtol: 0.5\n")
  inpact(0 out compare a.h5 b.h5 --tolerances loose.yaml)
  file(WRITE "${WORK}/bad.toml" "[CPRESS]\nrtoll = 1\n")
  inpact(2 out compare a.h5 b.h5 --tolerances bad.toml)
  expect_text("bad.toml:2: unknown setting 'rtoll'" "${out}" "bad tolerance file")

elseif(MODE STREQUAL "compare_renumbered")
  # Node 5 moved to the end of *NODE: another row, the same label: equal by label.
  string(REPLACE "\n5, 1, 0.5\n" "\n" moved "${deck}")
  string(REPLACE "\n115, 2, 2\n" "\n115, 2, 2\n5, 1, 0.5\n" moved "${moved}")
  file(WRITE "${WORK}/moved.inp" "${moved}")
  # Node 5 relabelled 905: a different model, and compare says which node.
  string(REPLACE "\n5, 1, 0.5\n" "\n905, 1, 0.5\n" relabelled "${deck}")
  foreach(pair "1, 1, 2, 5, 4|1, 1, 2, 905, 4" "2, 2, 3, 6, 5|2, 2, 3, 6, 905" "3, 4, 5, 8, 7|3, 4, 905, 8, 7"
               "4, 5, 6, 9, 8|4, 905, 6, 9, 8")
    string(REPLACE "|" ";" pair "${pair}")
    list(GET pair 0 from)
    list(GET pair 1 to)
    string(REPLACE "\n${from}\n" "\n${to}\n" relabelled "${relabelled}")
  endforeach()
  file(WRITE "${WORK}/relabelled.inp" "${relabelled}")
  inpact(0 out run patch.inp -j a -q)
  inpact(0 out run moved.inp -j moved -q)
  inpact(0 out run relabelled.inp -j relabelled -q)
  inpact(0 out compare a.h5 moved.h5)
  expect_text("SAME" "${out}" "moved node")
  inpact(1 out compare a.h5 relabelled.h5)
  expect_text("model: 1 node(s) of A not in B: 5" "${out}" "relabelled node")
  expect_text("step 'PRESS', field U: 1 location(s) of B not in A: node 905" "${out}" "relabelled node")

elseif(MODE STREQUAL "compare_incomplete")
  # I/O errors (exit 5) that say what is wrong: a .part file, an ABORTED run, a missing file,
  # a file that is not a results file. --allow-incomplete accepts the ABORTED one.
  inpact(0 out run patch.inp -j a -q)
  file(COPY_FILE "${WORK}/a.h5" "${WORK}/running.h5.part")
  inpact(5 out compare a.h5 running.h5.part)
  expect_text("a partial results file (.part)" "${out}" ".part")
  inpact(5 out compare a.h5 running.h5)
  expect_text("running.h5.part exists: the run is still writing it or was killed" "${out}" "missing with .part")
  inpact(5 out compare a.h5 patch.inp)
  expect_text("not an HDF5 file" "${out}" "a deck")
  inpact(4 out run "${SOURCE}/decks/verification/rigid_mode_abort.inp" -j aborted -q)
  inpact(5 out compare aborted.h5 aborted.h5)
  expect_text("status ABORTED: the run did not complete" "${out}" "ABORTED")
  inpact(0 out compare aborted.h5 aborted.h5 --allow-incomplete)
  inpact(2 out compare a.h5)

elseif(MODE STREQUAL "study_resume")
  # 4 cases on 2 workers; the table holds each case's load as its CPRESS; after one results
  # file is deleted, a rerun runs that case alone.
  inpact(0 out study patch.inp --grid load=5,10,15,20 -j 2 -o S ${collect})
  expect_text("4 to run on 2 worker(s)" "${out}" "first run")
  file(STRINGS "${WORK}/S/results.csv" rows)
  list(GET rows 0 header)
  if(NOT header STREQUAL "id,load,status,exit_code,wall_time_s,increments,iterations,cutbacks,max:CPRESS,max:-COPEN,sum:RF2@BOTTOM,message")
    string(APPEND failures "  results.csv header: ${header}\n")
  endif()
  foreach(i 1 2 3 4)
    math(EXPR load "${i} * 5")
    math(EXPR rf "${i} * 10")
    list(GET rows ${i} row)
    if(NOT row MATCHES "^c000${i},${load},completed,0,[0-9.]+,2,[0-9]+,0,${load},[0-9.e-]+,${rf},$")
      string(APPEND failures "  results.csv row ${i}: ${row}\n")
    endif()
  endforeach()
  file(REMOVE "${WORK}/S/cases/c0003/c0003.h5")
  inpact(0 out study patch.inp --grid load=5,10,15,20 -j 2 -o S ${collect})
  expect_text("3 already completed, 1 to run" "${out}" "resume")
  expect_text("c0003 completed" "${out}" "resume")
  # The results of a finished case whose case.result was lost (a killed study) are collected
  # without a rerun.
  file(REMOVE "${WORK}/S/cases/c0001/case.result")
  inpact(0 out study patch.inp --grid load=5,10,15,20 -j 2 -o S ${collect})
  expect_text("4 already completed, 0 to run" "${out}" "recollect")
  file(READ "${WORK}/S/results.csv" csv)
  expect_text("c0001,5,completed,0,,2," "${csv}" "recollected row")
  # ... and from the results file itself when the values the case wrote are lost too.
  file(REMOVE "${WORK}/S/cases/c0002/case.result" "${WORK}/S/cases/c0002/values.txt")
  inpact(0 out study patch.inp --grid load=5,10,15,20 -j 2 -o S ${collect})
  file(STRINGS "${WORK}/S/results.csv" rows)
  list(GET rows 2 row)
  if(NOT row MATCHES "^c0002,10,completed,0,,2,[0-9]+,0,10,[0-9.e-]+,20,$")
    string(APPEND failures "  results.csv row 2 collected from the results file: ${row}\n")
  endif()
  # Another study in the same folder is refused.
  inpact(2 out study patch.inp --grid load=1,2 -o S)
  expect_text("holds the manifest of another study" "${out}" "other study")

elseif(MODE STREQUAL "study_failed_case")
  # A deck error in one case: recorded with its exit code and message; the others complete.
  inpact(4 out study patch.inp --grid load=5,oops,15 -j 2 -o S ${collect})
  expect_text("c0002 failed (exit 3)" "${out}" "progress")
  file(READ "${WORK}/S/results.csv" csv)
  expect_text("c0002,oops,failed,3," "${csv}" "table")
  expect_text("error: *DSLOAD" "${csv}" "table message")
  expect_text("c0003,15,completed,0," "${csv}" "table")
  inpact(3 out study run-case c0002 -o S)
  inpact(0 out study run-case c0001 -o S)
  inpact(2 out study run-case c0099 -o S)

elseif(MODE STREQUAL "study_gnu_parallel")
  # GNU parallel runs two shards of the manifest on localhost; `study collect` writes the table.
  find_program(PARALLEL parallel)
  if(NOT PARALLEL)
    message(STATUS "GNU parallel not installed (Debian package parallel): skipped")
    return()  # ctest SKIP_REGULAR_EXPRESSION
  endif()
  execute_process(COMMAND "${PARALLEL}" --will-cite -j 2 "${INPACT}" study patch.inp --grid load=5,10,15,20 -o S -q
                          --collect max:CPRESS --shard {}/2 ::: 1 2
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
  if(NOT rc EQUAL 0)
    string(APPEND failures "  parallel: exit ${rc}\n${o}${e}\n")
  endif()
  inpact(0 out study collect -o S)
  expect_text("study: 4 completed, 0 failed, 0 pending" "${out}" "collect")
  # Each case again through run-case, ids from the manifest (already completed: nothing reruns).
  execute_process(COMMAND "${PARALLEL}" --will-cite -j 2 "${INPACT}" study run-case {} -o S ::: c0001 c0002 c0003 c0004
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
  if(NOT rc EQUAL 0)
    string(APPEND failures "  parallel run-case: exit ${rc}\n${o}${e}\n")
  endif()
  file(READ "${WORK}/S/results.csv" csv)
  expect_text("c0004,20,completed,0," "${csv}" "table")

elseif(MODE STREQUAL "study_fork_matches_exec")
  # The study's forked cases collect their values in memory; with --inpact EXE each case is an
  # exec and the values are read back from its results file. Both tables are the same, wall
  # times aside: every operation, a component, a node set, a missing set and a missing field.
  set(specs ${collect} --collect min:U2 --collect maxabs:U1 --collect max:CPRESS@NOSUCHSET --collect max:NOSUCHVAR)
  inpact(0 out study patch.inp --grid load=5,12.5 -j 2 -o F ${specs})
  inpact(0 out study patch.inp --grid load=5,12.5 -j 2 -o X ${specs} --inpact "${INPACT}")
  foreach(dir F X)
    file(STRINGS "${WORK}/${dir}/results.csv" rows_${dir})
    list(TRANSFORM rows_${dir} REPLACE "^(c[0-9]+,[^,]*,[^,]*,[^,]*),[0-9.]+," "\\1,WALL,")
  endforeach()
  if(NOT rows_F STREQUAL rows_X)
    string(APPEND failures "  forked and exec'd tables differ:\n  ${rows_F}\n  ${rows_X}\n")
  endif()
  list(GET rows_F 2 row)
  if(NOT row MATCHES "^c0002,12.5,completed,0,WALL,2,[0-9]+,0,12.5,[0-9.e-]+,25,-[0-9.e-]+,[0-9.e-]+,,,$")
    string(APPEND failures "  forked row 2: ${row}\n")
  endif()
  if(NOT EXISTS "${WORK}/F/cases/c0001/values.txt" OR EXISTS "${WORK}/X/cases/c0001/values.txt")
    string(APPEND failures "  values.txt: written by the forked case only\n")
  endif()
  file(READ "${WORK}/F/cases/c0001/timings.txt" timings)
  expect_text("output_s=" "${timings}" "timings")

elseif(MODE STREQUAL "study_ranks_per_case")
  # --ranks-per-case 2: each case a distributed run (mpirun -np 2 inpact run ...). Its results
  # are the one-process study's: the patch test's uniform pressure, 10 and 12.5, to 1e-6.
  set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
  set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
  set(ENV{OMPI_MCA_rmaps_base_oversubscribe} 1)
  inpact(0 out study patch.inp --grid load=10,12.5 -o R ${collect} --ranks-per-case 2)
  expect_text("to run on 1 worker(s) of 2 MPI ranks each" "${out}" "progress")
  inpact(0 out study patch.inp --grid load=10,12.5 -o S ${collect})
  file(READ "${WORK}/R/cases/c0002/c0002.dat" dat)
  expect_text("; 2 MPI ranks" "${dat}" "case .dat")
  file(WRITE "${WORK}/acceptance.toml" "[default]\nrtol = 1e-6\natol = 1e-6\nscale = \"frame-max\"\n[CSTATUS]\nexact = true\n")
  foreach(id c0001 c0002)
    inpact(0 out compare R/cases/${id}/${id}.h5 S/cases/${id}/${id}.h5 --tolerances acceptance.toml)
  endforeach()
  file(STRINGS "${WORK}/R/results.csv" rows)
  list(GET rows 2 row)
  if(NOT row MATCHES "^c0002,12.5,completed,0,")
    string(APPEND failures "  row 2 of the distributed study: ${row}\n")
  endif()

else()
  message(FATAL_ERROR "compare_study.cmake: unknown MODE=${MODE}")
endif()

if(failures)
  message(FATAL_ERROR "${MODE}:\n${failures}")
endif()
message(STATUS "${MODE}: ok")
