# The results files opened by real readers: h5py, meshio (XDMF sidecar) and ParaView 5.11's
# pvpython (VTKHDF and XDMF, rendered to PNG under xvfb-run; Debian's ParaView has no
# offscreen backend). The readers are Debian packages (python3-h5py python3-meshio
# python3-paraview xvfb) that .ci/install-deps.sh installs; a script whose reader is missing
# reports "skipped" (exit code 77). The samples are written once by test_io (PythonSample.*).
if(NOT TARGET test_io)
  return()
endif()
set(io_samples ${CMAKE_CURRENT_BINARY_DIR}/io_samples)
add_test(NAME io_write_reader_samples COMMAND test_io --gtest_filter=PythonSample.WriteJobs)
set_tests_properties(io_write_reader_samples PROPERTIES
  ENVIRONMENT INPACT_IO_SAMPLE_DIR=${io_samples} FIXTURES_SETUP io_reader_samples LABELS test_io)

set(io_python /usr/bin/python3)
add_test(NAME io_h5py_reads_every_dataset
  COMMAND ${io_python} ${CMAKE_CURRENT_SOURCE_DIR}/io/check_h5py.py ${io_samples})
add_test(NAME io_meshio_reads_every_xdmf_frame
  COMMAND ${io_python} ${CMAKE_CURRENT_SOURCE_DIR}/io/check_meshio.py ${io_samples})
set(io_reader_tests io_h5py_reads_every_dataset io_meshio_reads_every_xdmf_frame)

find_program(INPACT_PVPYTHON pvpython)
find_program(INPACT_XVFB_RUN xvfb-run)
if(INPACT_PVPYTHON AND INPACT_XVFB_RUN)
  add_test(NAME io_paraview_reads_and_renders
    COMMAND ${INPACT_XVFB_RUN} -a ${INPACT_PVPYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/check_paraview.py ${io_samples})
  list(APPEND io_reader_tests io_paraview_reads_and_renders)
else()
  message(STATUS "pvpython or xvfb-run not found: the ParaView reader test is not registered")
endif()
set_tests_properties(${io_reader_tests} PROPERTIES
  FIXTURES_REQUIRED io_reader_samples SKIP_RETURN_CODE 77 LABELS test_io TIMEOUT 120)
if(INPACT_PVPYTHON AND INPACT_XVFB_RUN)
  # Alone: under the load of the other tests (2 cores) the X server sometimes failed to come up
  # in time and the test aborted before ParaView read anything.
  set_tests_properties(io_paraview_reads_and_renders PROPERTIES RUN_SERIAL TRUE)
endif()
