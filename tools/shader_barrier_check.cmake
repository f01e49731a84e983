# GLSL ES 3.10 (section 8.16): barrier() may only appear in main(), outside any control flow,
# and not after a return. A driver may reject a shader that breaks this, or hang on it when
# some invocations of a group leave before the barrier the others wait at; glslangValidator
# and llvmpipe accept it, so the build checks it here on the expanded text of every compute
# shader (tools/shader_expand.cmake).
#
# Included: check_shader_barriers(<text> <name>) fails with a message naming the shader.
# Standalone (tests/gpu/shader_check/): cmake -DBARRIER_CHECK_FILE=x.comp -P shader_barrier_check.cmake

function(check_shader_barriers text name)
  # Comments out; ';' would split CMake lists, '`' never appears in GLSL. Line comments first:
  # a "/*" inside one ("speed/*.comp") would otherwise open a block comment that never closes,
  # and CMake's regex backtracks through the rest of the shader until its stack overflows.
  string(REGEX REPLACE "//[^\n]*" "" text "${text}")
  string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" " " text "${text}")
  string(REPLACE ";" "`" text "${text}")
  string(REGEX MATCH "void[ \t\r\n]+main[ \t\r\n]*\\([ \t\r\n]*(void)?[ \t\r\n]*\\)[ \t\r\n]*{.*"
         main "${text}")
  if(main STREQUAL "")
    return()
  endif()
  string(FIND "${main}" "{" open)
  string(SUBSTRING "${main}" ${open} -1 main)
  # Tokens in order: braces and statements (each up to its ';').
  string(REGEX MATCHALL "[{}]|[^{}`]+`?" tokens "${main}")
  set(depth 0)
  set(returned "")
  foreach(token IN LISTS tokens)
    if(token STREQUAL "{")
      math(EXPR depth "${depth} + 1")
    elseif(token STREQUAL "}")
      math(EXPR depth "${depth} - 1")
      if(depth EQUAL 0)
        break() # end of main()
      endif()
    else()
      string(STRIP "${token}" statement)
      if(statement MATCHES "(^|[^A-Za-z0-9_])barrier[ \t\r\n]*\\(")
        if(NOT returned STREQUAL "")
          message(FATAL_ERROR "${name}: return before barrier() in main() ('${returned}'); "
                              "GLSL ES 3.10 requires every invocation to reach every barrier: "
                              "guard the work with a flag instead of returning")
        endif()
        if(NOT depth EQUAL 1 OR NOT statement MATCHES "^barrier[ \t\r\n]*\\([ \t\r\n]*\\)[ \t\r\n]*`$")
          string(REPLACE "`" ";" statement "${statement}")
          message(FATAL_ERROR "${name}: barrier() inside control flow in main() ('${statement}'); "
                              "GLSL ES 3.10 allows it only as a statement of its own at main()'s top level")
        endif()
      endif()
      if(returned STREQUAL "" AND statement MATCHES "(^|[^A-Za-z0-9_])return([^A-Za-z0-9_]|$)")
        string(REPLACE "`" ";" returned "${statement}")
      endif()
    endif()
  endforeach()
endfunction()

if(DEFINED BARRIER_CHECK_FILE)
  file(READ "${BARRIER_CHECK_FILE}" shader_text)
  check_shader_barriers("${shader_text}" "${BARRIER_CHECK_FILE}")
  message(STATUS "${BARRIER_CHECK_FILE}: barriers fine")
endif()
