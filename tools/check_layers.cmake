# The layering rule of docs/architecture.md, checked on every build: a module includes only
# itself and the modules below it. Fails listing each include that points the wrong way.
#   cmake -DROOT=<source root> [-DSTAMP=<file>] -P check_layers.cmake
# Modules (a folder's first path component in an include, relative to app/ or the root), each
# allowed itself and the modules listed for it, no more (docs/architecture.md draws them):
#   model  <-  core  <-  files  <-  scan  <-  exports
#   core  <-  gpu  <-  speed  <-  solver  <-  render  <-  session  (session: scan, exports too)
#   model, core, files  <-  workflow  <-  config  <-  input
#   workflow  <-  script, autosave;  workflow, session  <-  engine
#   exports, workflow  <-  net (the DICOM network node)
#   everything  <-  ui  <-  kiosk  <-  cli
# ui/ sits at the root beside app/ (the design's top level) and is the module "ui".
# platform/ is beside and below them all: it includes nothing of app/; the console's input and
# scripts, the UI and the composition roots (kiosk, cli) may include it.
cmake_minimum_required(VERSION 3.25)

set(allowed_model "model")
set(allowed_core "model;core")
set(allowed_files "model;core;files")
set(allowed_scan "model;core;files;scan")
set(allowed_exports "model;core;files;scan;exports")
set(allowed_gpu "model;core;gpu")
set(allowed_speed "model;core;gpu;speed")
set(allowed_solver "model;core;gpu;speed;solver")
set(allowed_render "model;core;gpu;speed;solver;render")
set(allowed_session "model;core;files;scan;exports;gpu;speed;solver;render;session")
set(allowed_workflow "model;core;files;workflow")
set(allowed_config "model;core;workflow;config")
set(allowed_input "model;core;workflow;config;input;platform")
set(allowed_script "model;core;files;scan;workflow;script;platform")
set(allowed_autosave "model;core;files;workflow;autosave")
set(allowed_engine "model;core;files;scan;exports;gpu;speed;solver;render;session;workflow;engine")
set(allowed_net "model;core;files;scan;exports;workflow;net")
set(allowed_ui "model;core;gpu;speed;render;session;workflow;ui;platform")
set(allowed_kiosk "model;core;files;scan;exports;gpu;speed;solver;render;session;workflow;config;input;script;autosave;engine;net;ui;kiosk;platform")
set(allowed_cli "model;core;files;scan;exports;gpu;speed;solver;render;session;workflow;config;input;script;autosave;engine;net;ui;kiosk;cli;platform")
set(allowed_platform "platform")
set(modules model core files scan exports gpu speed solver render session workflow config input
  script autosave engine net ui kiosk cli platform)

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
