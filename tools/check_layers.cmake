# The layering rule of docs/architecture.md, checked on every build: a module includes only
# itself and the modules below it. Fails listing each include that points the wrong way.
#   cmake -DROOT=<source root> [-DSTAMP=<file>] -P check_layers.cmake
# Modules (a folder's first path component in an include, relative to app/ or the root):
#   core  <- io, gpu  <- speed  <- solver  <- render  <- session  <- ui  <- kiosk  <- cli
#   core, solver's and speed's plain types  <- workflow  <- config, ui, kiosk
# ui/ sits at the root beside app/ (the design's top level) and is the module "ui".
# platform/ is beside and below them all: only the composition roots (cli, kiosk) and ui may
# include it, and it includes nothing of app/.
cmake_minimum_required(VERSION 3.25)

set(allowed_core "core")
set(allowed_io "core;io")
set(allowed_gpu "core;gpu")
set(allowed_speed "core;gpu;speed")
set(allowed_solver "core;gpu;speed;solver")
set(allowed_render "core;gpu;speed;solver;render")
set(allowed_session "core;io;gpu;speed;solver;render;session")
# workflow may name solver's and speed's GL-free structs (level_set_params.hpp, solver_types.hpp,
# speed_kind.hpp); its library links no solver code, so anything more fails its link.
set(allowed_workflow "core;speed;solver;workflow")
set(allowed_config "core;speed;workflow;config")
set(allowed_ui "core;gpu;speed;render;session;workflow;ui;platform")
set(allowed_kiosk "core;io;gpu;speed;solver;render;session;workflow;config;ui;kiosk;platform")
set(allowed_cli "core;io;gpu;speed;solver;render;session;workflow;config;kiosk;cli;platform")
set(allowed_platform "platform")
set(modules core io gpu speed solver render session workflow config ui cli kiosk platform)

if(NOT ROOT)
  message(FATAL_ERROR "check_layers: give -DROOT=<source root>")
endif()
file(GLOB_RECURSE sources RELATIVE "${ROOT}"
  "${ROOT}/app/*.cpp" "${ROOT}/app/*.hpp" "${ROOT}/platform/*.cpp" "${ROOT}/platform/*.hpp"
  "${ROOT}/ui/*.cpp" "${ROOT}/ui/*.hpp")
set(violations "")
foreach(rel IN LISTS sources)
  if(rel MATCHES "^app/([a-z_]+)/")
    set(module "${CMAKE_MATCH_1}")
  elseif(rel MATCHES "^platform/")
    set(module "platform")
  elseif(rel MATCHES "^ui/")
    set(module "ui")
  else()
    continue()
  endif()
  if(NOT DEFINED allowed_${module})
    list(APPEND violations "${rel}: module '${module}' has no place in the layering rule (tools/check_layers.cmake)")
    continue()
  endif()
  file(STRINGS "${ROOT}/${rel}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"[a-z_]+/")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([a-z_]+)/.*" "\\1" target "${line}")
    list(FIND modules "${target}" known)
    if(known EQUAL -1)
      continue() # not one of ours (a generated or third-party header)
    endif()
    list(FIND allowed_${module} "${target}" ok)
    if(ok EQUAL -1)
      string(REPLACE ";" ", " may "${allowed_${module}}")
      list(APPEND violations "${rel} includes ${target}/: ${module} may include ${may}")
    endif()
  endforeach()
endforeach()

if(violations)
  list(LENGTH violations count)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "layering: ${count} include(s) against the rule in docs/architecture.md:\n  ${text}")
endif()
if(STAMP)
  file(WRITE "${STAMP}" "ok\n")
endif()
