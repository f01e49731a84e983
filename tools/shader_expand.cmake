# Expands `#include "file"` lines of one GLSL ES shader (paths relative to SHADER_ROOT), writes
# the result to OUTPUT and validates it with glslangValidator, so that a shader error fails the
# build with the shader's own file name rather than at run time on the appliance. Compute
# shaders must also keep GLSL ES's barrier rule (tools/shader_barrier_check.cmake), which
# glslangValidator does not check.
#   cmake -DSHADER_ROOT=... -DINPUT=... -DOUTPUT=... -DVALIDATOR=... -P shader_expand.cmake
cmake_minimum_required(VERSION 3.25)

function(expand_file path depth out_var)
  if(depth GREATER 8)
    message(FATAL_ERROR "${path}: #include nested too deeply")
  endif()
  # file(STRINGS) drops empty lines and splits on ';' so read raw and split ourselves.
  file(READ "${path}" text)
  string(REPLACE ";" "\\;" text "${text}")
  # CMake does not split a list at a ';' inside square brackets: one unmatched '[' (an interval
  # in a comment) would join the rest of the file into one line. Stand-ins while split.
  string(REPLACE "[" "@EXPAND_LSQB@" text "${text}")
  string(REPLACE "]" "@EXPAND_RSQB@" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(result "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*#include[ \t]+\"([^\"]+)\"")
      set(inc "${SHADER_ROOT}/${CMAKE_MATCH_1}")
      if(NOT EXISTS "${inc}")
        message(FATAL_ERROR "${path}: included file ${CMAKE_MATCH_1} not found under ${SHADER_ROOT}")
      endif()
      math(EXPR next "${depth} + 1")
      expand_file("${inc}" ${next} inc_text)
      string(APPEND result "${inc_text}")
    else()
      string(REPLACE "@EXPAND_LSQB@" "[" line "${line}")
      string(REPLACE "@EXPAND_RSQB@" "]" line "${line}")
      string(APPEND result "${line}\n")
    endif()
  endforeach()
  set(${out_var} "${result}" PARENT_SCOPE)
endfunction()

expand_file("${INPUT}" 0 expanded)
file(WRITE "${OUTPUT}.tmp" "${expanded}")

# Validate with the constants the program injects at run time given placeholder values.
get_filename_component(ext "${INPUT}" LAST_EXT)
string(SUBSTRING "${ext}" 1 -1 stage)
if(stage STREQUAL "comp")
  include("${CMAKE_CURRENT_LIST_DIR}/shader_barrier_check.cmake")
  check_shader_barriers("${expanded}" "${INPUT}")
endif()
execute_process(COMMAND "${VALIDATOR}" -S ${stage} "${OUTPUT}.tmp"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  string(REPLACE "${OUTPUT}.tmp" "${INPUT}" out "${out}")
  message(FATAL_ERROR "glslangValidator rejected ${INPUT} (after #include expansion):\n${out}${err}")
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
