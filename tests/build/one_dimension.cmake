# The test build/one_dimension: configures and builds the program for one
# dimension (-DCONTACT_DIMENSIONS=<DIMENSION>), then
#  - runs the paper's scene in that dimension for two steps, which must
#    succeed, and
#  - runs it in the other dimension, which must be refused before anything
#    runs, with a message that names the entry 'Dimension', the compiled
#    dimension and the CMake option.
# What it prints is compared with one_dimension.output.
#
# Called as  cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DDIMENSION=2
#                  -DEXPECTED=... -DGENERATOR=... -DDEAL_II_DIR=...
#                  -DCXX_COMPILER=... -P one_dimension.cmake
# (the generator, deal.II and the compiler of the build that runs it).

if(DIMENSION STREQUAL "2")
  set(other 3)
else()
  set(other 2)
endif()
set(tree ${BINARY_DIR}/one-dimension-${DIMENSION})

execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${tree} -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release -DCONTACT_DIMENSIONS=${DIMENSION}
    -Ddeal.II_DIR=${DEAL_II_DIR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "Configuring for dimension ${DIMENSION} failed:\n${log}")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} --build ${tree} -j2 --target contact
  RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "Building for dimension ${DIMENSION} failed:\n${log}")
endif()

set(common
  --set "Time/End time=0.02" --set "Time/Time step=0.01"
  --set "Output/VTU interval=0"
  --set "Output/Time series=false" --set "Output/Gamma3 history=false"
  --set "Output/Progress interval=0" --set "Output/Print timings=false")
set(report "")
foreach(dim ${DIMENSION} ${other})
  if(dim STREQUAL "3")
    set(scene ${SOURCE_DIR}/prm/barboteu2015_3d.prm)
  else()
    set(scene ${SOURCE_DIR}/prm/barboteu2015.prm)
  endif()
  execute_process(
    COMMAND ${tree}/contact ${common}
      --set "Output/Output directory=${tree}/run-${dim}d" ${scene}
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(status EQUAL 0)
    set(result "exit status 0")
  else()
    set(result "exit status non-zero")
  endif()
  # The refusal's message, as the program prints it (one line).
  string(REGEX MATCH "Entry 'Dimension'[^\n]*" refusal "${out}${err}")
  string(APPEND report "Dimension = ${dim}: ${result}\n")
  if(refusal)
    string(APPEND report "${refusal}\n")
  endif()
endforeach()
message(STATUS "${report}")
file(READ ${EXPECTED} expected)
if(NOT report STREQUAL expected)
  message(FATAL_ERROR "Expected:\n${expected}\nGot:\n${report}")
endif()
