# Compiles each of SOURCES (a ;-list, or |-separated) with CXX and the include directories
# INCLUDES (|-separated), syntax only, and checks what its first line says:
#   // EXPECT: OK      must compile
#   // EXPECT: <text>  must fail, and the first error printed must contain <text>
# Writes a JUnit file to JUNIT when given (catkin's run_tests reads it); fails on any mismatch.
#   cmake -DCXX=g++ -DINCLUDES="a|b" -DSOURCES="x.cpp|y.cpp" [-DJUNIT=out.xml] -P <this file>
string(REPLACE "|" ";" SOURCES "${SOURCES}")
string(REPLACE "|" ";" INCLUDES "${INCLUDES}")
set(_flags -std=c++17 -fsyntax-only -fdiagnostics-color=never)
foreach(_dir IN LISTS INCLUDES)
  list(APPEND _flags "-I${_dir}")
endforeach()

set(_failures 0)
set(_cases "")
foreach(_source IN LISTS SOURCES)
  get_filename_component(_name "${_source}" NAME_WE)
  file(STRINGS "${_source}" _first LIMIT_COUNT 1)
  string(REGEX REPLACE "^// EXPECT: *" "" _expect "${_first}")
  execute_process(COMMAND "${CXX}" ${_flags} "${_source}"
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  string(REGEX MATCH "error: [^\n]*" _error "${_out}")
  set(_problem "")
  if(_first STREQUAL _expect)
    set(_problem "no '// EXPECT:' first line")
  elseif(_expect STREQUAL "OK")
    if(NOT _rc EQUAL 0)
      set(_problem "expected to compile, got: ${_error}")
    endif()
  elseif(_rc EQUAL 0)
    set(_problem "expected an error containing '${_expect}', but it compiled")
  else()
    string(FIND "${_error}" "${_expect}" _at)
    if(_at LESS 0)
      set(_problem "first error is '${_error}', expected it to contain '${_expect}'")
    endif()
  endif()
  if(_problem)
    math(EXPR _failures "${_failures} + 1")
    message("FAIL ${_name}: ${_problem}")
    string(REPLACE "&" "&amp;" _problem "${_problem}")
    string(REPLACE "<" "&lt;" _problem "${_problem}")
    string(REPLACE ">" "&gt;" _problem "${_problem}")
    string(REPLACE "\"" "&quot;" _problem "${_problem}")
    string(APPEND _cases "  <testcase classname=\"compile_errors\" name=\"${_name}\">"
      "<failure message=\"${_problem}\"/></testcase>\n")
  else()
    message("PASS ${_name} (${_expect})")
    string(APPEND _cases "  <testcase classname=\"compile_errors\" name=\"${_name}\"/>\n")
  endif()
endforeach()

list(LENGTH SOURCES _count)
if(JUNIT)
  file(WRITE "${JUNIT}" "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<testsuite name=\"compile_errors\" tests=\"${_count}\" failures=\"${_failures}\" "
    "errors=\"0\">\n${_cases}</testsuite>\n")
endif()
if(_failures GREATER 0)
  message(FATAL_ERROR "${_failures} of ${_count} compile-error cases failed")
endif()
