# Runs `inpact check DECK` and checks its exit code and its output (stdout + stderr together).
#
#   cmake -DINPACT=path/to/inpact -DDIR=folder -DDECK=name.inp
#         [-DEXPECT=text] [-DEXPECT_EXIT=3] [-DGENERATE=binary|long_line] -P expect_error.cmake
#
# The check runs inside DIR with the deck's bare name, so the messages cite paths relative to
# DIR and no absolute path needs to be written anywhere. Expectations come from the deck itself,
# from comment lines
#     ** expect: <text that must appear in the output>
#     ** expect-exit: <code>            (default 3, a deck error)
# and from -DEXPECT / -DEXPECT_EXIT. GENERATE writes the deck first (into DIR), for input that
# should not be committed: binary garbage, a line of 800,000 characters.
cmake_minimum_required(VERSION 3.22)
foreach(var INPACT DIR DECK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_error.cmake: -D${var}=... is required")
  endif()
endforeach()

set(deck "${DIR}/${DECK}")
set(expected_exit 3)
set(expected "")
if(DEFINED EXPECT_EXIT)
  set(expected_exit "${EXPECT_EXIT}")
endif()
if(DEFINED EXPECT)
  list(APPEND expected "${EXPECT}")
endif()

if(GENERATE STREQUAL "binary")
  # An ELF-like header: 0x7f 'E' 'L' 'F' 0x02 0x01 0x01 ... (no NUL: CMake strings cannot hold one;
  # any control byte but tab, CR, LF and FF makes the reader refuse the file).
  string(ASCII 127 69 76 70 2 1 1 3 4 5 6 7 8 14 15 16 17 18 19 20 header)
  string(REPEAT "${header}" 64 garbage)
  file(MAKE_DIRECTORY "${DIR}")
  file(WRITE "${deck}" "${garbage}")
elseif(GENERATE STREQUAL "long_line")
  # A *NODE data line of 200,000 fields (800,000 characters).
  string(REPEAT ", 0." 199999 fields)
  file(MAKE_DIRECTORY "${DIR}")
  file(WRITE "${deck}" "*NODE\n1${fields}\n")
elseif(DEFINED GENERATE)
  message(FATAL_ERROR "expect_error.cmake: unknown GENERATE=${GENERATE}")
else()
  file(STRINGS "${deck}" lines REGEX "^\\*\\* expect")
  foreach(line IN LISTS lines)
    if(line MATCHES "^\\*\\* expect-exit: *([0-9]+)")
      set(expected_exit "${CMAKE_MATCH_1}")
    elseif(line MATCHES "^\\*\\* expect: (.*)$")
      list(APPEND expected "${CMAKE_MATCH_1}")
    endif()
  endforeach()
endif()
if(NOT expected)
  message(FATAL_ERROR "expect_error.cmake: ${DECK} states no expectation (** expect: ...)")
endif()

execute_process(COMMAND "${INPACT}" check "${DECK}"
                WORKING_DIRECTORY "${DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
set(output "${out}${err}")
string(LENGTH "${output}" n)
if(n GREATER 4000)  # a long line's message echoes a lot: show the start only
  string(SUBSTRING "${output}" 0 4000 output_shown)
  string(APPEND output_shown "\n... (${n} characters in all)")
else()
  set(output_shown "${output}")
endif()

set(failures "")
if(NOT rc STREQUAL expected_exit)
  string(APPEND failures "  exit code ${rc}, expected ${expected_exit}\n")
endif()
foreach(text IN LISTS expected)
  string(FIND "${output}" "${text}" at)
  if(at EQUAL -1)
    string(APPEND failures "  missing from the output: ${text}\n")
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "inpact check ${DECK} (in ${DIR}):\n${failures}--- output ---\n${output_shown}")
endif()
message(STATUS "inpact check ${DECK}: exit ${rc} and the expected message")
