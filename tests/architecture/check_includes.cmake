# The include direction between folders (docs/architecture.md). The CMake
# targets stop a link the wrong way, but they share one include root, so only
# this check stops a stray #include. Run: cmake -DROOT=<tree> -P check_includes.cmake
#
# Each folder has a rank; a file may include its own folder or a folder of a
# lower rank, never a higher one and never a sibling of the same rank.
#   top level: engine 0 <- design 1 <- report 2, python 2 <- app 3
#   engine:    common 0 <- numerics 1 <- environment 2 <- lines 3, hull 3 <- analysis 4
#   design:    project 0 <- model 1 <- {criteria 2, import 2} <- analysis 3 <- soz 4 <- optimization 5 <- stages 6 <- results 7 <- workflow 8
# Also: design/project includes no engine header (the project model is plain
# data), and engine includes no yaml-cpp (YAML belongs to design).
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P check_includes.cmake")
endif()

set(rank_top_engine 0)
set(rank_top_design 1)
set(rank_top_report 2)
set(rank_top_python 2)  # the Python bindings: a thin layer over design, beside report
set(rank_top_app 3)
set(rank_engine_common 0)
set(rank_engine_numerics 1)
set(rank_engine_environment 2)
set(rank_engine_lines 3)
set(rank_engine_hull 3)
set(rank_engine_analysis 4)
set(rank_design_project 0)
set(rank_design_model 1)
set(rank_design_criteria 2)
set(rank_design_import 2)  # MoorDyn decks in and out: needs project and model only
set(rank_design_analysis 3)
set(rank_design_soz 4)
set(rank_design_optimization 5)
set(rank_design_stages 6)
set(rank_design_results 7)
set(rank_design_workflow 8)

# place(<path below ROOT> <out-top> <out-sub>): the top folder and, in engine
# and design, the subfolder a path belongs to.
function(place path out_top out_sub)
  string(REPLACE "/" ";" parts "${path}")
  list(GET parts 0 top)
  set(sub "")
  if(top STREQUAL "engine" OR top STREQUAL "design")
    list(LENGTH parts n)
    if(n GREATER 2)
      list(GET parts 1 sub)
    endif()
  endif()
  set(${out_top} "${top}" PARENT_SCOPE)
  set(${out_sub} "${sub}" PARENT_SCOPE)
endfunction()

set(violations "")
set(checked 0)
file(GLOB_RECURSE files RELATIVE ${ROOT} ${ROOT}/engine/*.?pp ${ROOT}/design/*.?pp ${ROOT}/report/*.?pp
     ${ROOT}/app/*.?pp ${ROOT}/python/*.?pp)
foreach(file ${files})
  place("${file}" top sub)
  if(NOT DEFINED rank_top_${top})
    continue()
  endif()
  if(NOT sub STREQUAL "" AND NOT DEFINED rank_${top}_${sub})
    list(APPEND violations "${file}: folder ${top}/${sub} has no place in the order (add it to check_includes.cmake and docs/architecture.md)")
    continue()
  endif()
  math(EXPR checked "${checked} + 1")
  file(STRINGS ${ROOT}/${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  foreach(line ${includes})
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*" "\\1" target "${line}")
    if(file MATCHES "^engine/" AND target MATCHES "^yaml-cpp/")
      list(APPEND violations "${file}: includes ${target}: YAML belongs to design, not engine")
      continue()
    endif()
    place("${target}" ttop tsub)
    if(NOT DEFINED rank_top_${ttop})
      continue()  # a system or third-party header
    endif()
    if(sub STREQUAL "project" AND top STREQUAL "design" AND ttop STREQUAL "engine")
      list(APPEND violations "${file}: includes ${target}: design/project is plain data and includes no engine header")
      continue()
    endif()
    if(NOT ttop STREQUAL top)
      if(NOT rank_top_${ttop} LESS rank_top_${top})
        list(APPEND violations "${file}: includes ${target}: ${top}/ may not include ${ttop}/ (engine <- design <- {report, python} <- app)")
      endif()
      continue()
    endif()
    if(sub STREQUAL "" OR tsub STREQUAL "" OR tsub STREQUAL sub)
      continue()
    endif()
    if(NOT DEFINED rank_${ttop}_${tsub})
      list(APPEND violations "${file}: includes ${target}: folder ${ttop}/${tsub} has no place in the order")
    elseif(NOT rank_${ttop}_${tsub} LESS rank_${top}_${sub})
      list(APPEND violations "${file}: includes ${target}: ${top}/${sub} may not include ${ttop}/${tsub} (see the order in tests/architecture/check_includes.cmake)")
    endif()
  endforeach()
endforeach()

if(checked EQUAL 0)
  message(FATAL_ERROR "no source file found below ${ROOT}")
endif()
list(LENGTH violations count)
if(count GREATER 0)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "${count} include(s) against the folder order:\n  ${text}")
endif()
message(STATUS "include direction: ${checked} files follow the folder order")
