# An installed spiral works from anywhere: `cmake --install` into a fresh
# prefix, then the installed `spiral` runs the installed OC4 scenario (its
# data found through the scenario's relative paths) from an unrelated
# working directory, and `spiral --version` names the version and commit.
# Run by CTest: cmake -DBUILD=<build dir> -DVERSION=<x.y.z> -P check_install.cmake
set(prefix ${BUILD}/install-check)
file(REMOVE_RECURSE ${prefix})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
foreach(installed bin/spiral share/spiral/scenarios/deepwater-fps.yaml
                  share/spiral/scenarios/data/hydro/oc4-semi/marin_semi.1 share/doc/spiral/README.md
                  share/doc/spiral/project-format.md)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "not installed: ${installed}")
  endif()
endforeach()
file(MAKE_DIRECTORY ${prefix}/elsewhere)
execute_process(COMMAND ${prefix}/bin/spiral run ${prefix}/share/spiral/scenarios/oc4-semisubmersible.yaml
                        --out run --until preliminary
                WORKING_DIRECTORY ${prefix}/elsewhere RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${prefix}/elsewhere/run/preliminary/report.pdf)
  message(FATAL_ERROR "the installed spiral run failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${prefix}/bin/spiral --version OUTPUT_VARIABLE version)
if(NOT version MATCHES "spiral ${VERSION} \\(commit ([0-9a-f]+|unknown)\\)")
  message(FATAL_ERROR "spiral --version printed: ${version}")
endif()
file(REMOVE_RECURSE ${prefix})
