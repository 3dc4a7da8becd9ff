# The solver's layers (docs/architecture.md), checked on every file of solver/:
#   - solver/ never includes Qt (a Qt header, <Q…> or <Qt…>);
#   - each folder includes only from its own layer and those below it, in this order:
#       core < spec < parse < kinematics < inertia < hydraulics < contact < dynamics < compile < integrate
#            < collision < io < reference < solver/pipeline.h
#     so core/ includes nothing from another solver folder.
# Run: cmake -DROOT=<source dir> -P tests/layering/check_layers.cmake (ctest: solver.layering).
if(NOT ROOT)
  message(FATAL_ERROR "give -DROOT=<the source directory>")
endif()
set(layers core spec parse kinematics inertia hydraulics contact dynamics compile integrate collision io reference pipeline)

file(GLOB_RECURSE files RELATIVE ${ROOT} ${ROOT}/solver/*.h ${ROOT}/solver/*.cpp)
set(problems "")
set(count 0)
foreach(f IN LISTS files)
  math(EXPR count "${count} + 1")
  # the file's layer: its folder under solver/, or "pipeline" for solver/pipeline.*
  string(REGEX MATCH "^solver/([a-z_]+)/" m "${f}")
  if(m)
    set(own "${CMAKE_MATCH_1}")
  else()
    set(own pipeline)
  endif()
  list(FIND layers "${own}" ownRank)
  if(ownRank LESS 0)
    string(APPEND problems "${f}: folder '${own}' is not in the list of layers (add it to tests/layering/check_layers.cmake and docs/architecture.md)\n")
    continue()
  endif()
  file(STRINGS "${ROOT}/${f}" includes REGEX "^[ \t]*#[ \t]*include")
  foreach(line IN LISTS includes)
    if(line MATCHES "#[ \t]*include[ \t]*[<\"](Q[A-Za-z0-9_]*|Qt[A-Za-z0-9_]*/[^>\"]*)[>\"]")
      string(APPEND problems "${f}: includes Qt (${CMAKE_MATCH_1}): the solver is Qt-free\n")
    endif()
    if(line MATCHES "#[ \t]*include[ \t]*\"solver/([a-z_]+)(/|\\.h)")
      set(to "${CMAKE_MATCH_1}")
      if(CMAKE_MATCH_2 STREQUAL ".h")
        set(to pipeline)
      endif()
      list(FIND layers "${to}" toRank)
      if(toRank GREATER ownRank)
        string(APPEND problems "${f}: ${own}/ includes from ${to}/, a layer above it: ${line}\n")
      endif()
    endif()
  endforeach()
endforeach()

if(count LESS 50)
  message(FATAL_ERROR "found only ${count} solver files under ${ROOT}/solver: wrong ROOT?")
endif()
if(problems)
  message(FATAL_ERROR "layering broken:\n${problems}")
endif()
message(STATUS "layering: ${count} solver files, no include against the layers, no Qt")
