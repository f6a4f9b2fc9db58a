# The test build/core_alone: configures and builds the program once more,
# with the core alone and for one dimension (-DCONTACT_PARTS=core
# -DCONTACT_DIMENSIONS=<DIMENSION>: one library, so that the suite compiles
# one extra library, not two), then
#  - runs the paper's scene in that dimension for two steps with the
#    friction method of the core (Solver/Friction method = convexification),
#    which must succeed and print the lines that the full build (FULL, the
#    program of the build that runs this test) prints for the same run,
#    those of the parts aside;
#  - runs it in the other dimension, which must be refused before anything
#    runs, with a message that names the entry 'Dimension', the compiled
#    dimension and the CMake option;
#  - runs it with Solver/Friction method = Newton and with the scene's
#    time series (each a part), each refused with a message that names the
#    entry, the part and the CMake option;
#  - compares the entries that the build declares with the full build's: a
#    .prm for the full build reads in the core's, which refuses it only
#    where it asks for a missing part.
# What it prints is compared with core_alone.output.
#
# Called as  cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DDIMENSION=2
#                  -DFULL=... -DEXPECTED=... -DGENERATOR=... -DDEAL_II_DIR=...
#                  -DCXX_COMPILER=... -P core_alone.cmake
# (the generator, deal.II and the compiler of the build that runs it).

if(DIMENSION STREQUAL "2")
  set(other 3)
else()
  set(other 2)
endif()
set(tree ${BINARY_DIR}/core-alone-${DIMENSION}d)

execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${tree} -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release -DCONTACT_DIMENSIONS=${DIMENSION}
    -DCONTACT_PARTS=core
    -Ddeal.II_DIR=${DEAL_II_DIR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "Configuring the core for dimension ${DIMENSION} failed:\n${log}")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} --build ${tree} -j2 --target contact
  RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "Building the core for dimension ${DIMENSION} failed:\n${log}")
endif()

set(common
  --set "Time/End time=0.02" --set "Time/Time step=0.01"
  --set "Output/VTU interval=0" --set "Output/Gamma3 history=false"
  --set "Output/Progress interval=0" --set "Output/Print timings=false")
set(core_method --set "Solver/Friction method=convexification")
set(no_series --set "Output/Time series=false")
set(report "")

# Runs `program` on the scene of dimension `dim` with the further arguments;
# sets `result` ("exit status 0" or "exit status non-zero"), `out` (what it
# printed) and `refusal` (the first line of a message that names an entry).
function(run_scene program dim name)
  if(dim STREQUAL "3")
    set(scene ${SOURCE_DIR}/prm/barboteu2015_3d.prm)
  else()
    set(scene ${SOURCE_DIR}/prm/barboteu2015.prm)
  endif()
  execute_process(
    COMMAND ${program} ${common} ${ARGN}
      --set "Output/Output directory=${tree}/run-${name}" ${scene}
    RESULT_VARIABLE status OUTPUT_VARIABLE printed ERROR_VARIABLE errors)
  if(status EQUAL 0)
    set(result "exit status 0" PARENT_SCOPE)
  else()
    set(result "exit status non-zero" PARENT_SCOPE)
  endif()
  set(out "${printed}" PARENT_SCOPE)
  string(REGEX MATCH "Entry '[^\n]*" line "${printed}${errors}")
  set(refusal "${line}" PARENT_SCOPE)
endfunction()

# The run of the core, and the same run of the full build: every line that
# the core prints, the full build prints too, in the same order (the lines
# of its parts come in between), but for the output directory's name.
run_scene(${tree}/contact ${DIMENSION} core ${core_method} ${no_series})
string(APPEND report "Dimension = ${DIMENSION}, the core's friction method: ${result}\n")
set(core_out "${out}")
run_scene(${FULL} ${DIMENSION} full ${core_method} ${no_series})
set(full_out "${out}")
string(REPLACE "run-core" "run-<name>" core_out "${core_out}")
string(REPLACE "run-full" "run-<name>" full_out "${full_out}")
string(REPLACE ";" "<semicolon>" core_out "${core_out}")
string(REPLACE ";" "<semicolon>" full_out "${full_out}")
string(REPLACE "\n" ";" core_lines "${core_out}")
string(REPLACE "\n" ";" full_lines "${full_out}")
list(LENGTH core_lines n_core)
set(missing "")
foreach(line ${core_lines})
  list(FIND full_lines "${line}" at)
  if(at LESS 0)
    set(missing "${line}")
    break()
  endif()
  math(EXPR at "${at} + 1")
  list(SUBLIST full_lines ${at} -1 full_lines)
endforeach()
if(missing STREQUAL "")
  string(APPEND report "its ${n_core} lines are the full build's, in order: yes\n")
else()
  string(APPEND report "its lines are the full build's, in order: no, not \"${missing}\"\n")
endif()

run_scene(${tree}/contact ${other} other-dimension ${core_method} ${no_series})
string(APPEND report "Dimension = ${other}: ${result}\n${refusal}\n")
run_scene(${tree}/contact ${DIMENSION} newton ${no_series}
  --set "Solver/Friction method=Newton")
string(APPEND report "Solver/Friction method = Newton: ${result}\n${refusal}\n")
run_scene(${tree}/contact ${DIMENSION} series ${core_method})
string(APPEND report "The scene's time series: ${result}\n${refusal}\n")

# The entries, "Subsection/Entry", sorted.
function(entries program variable)
  execute_process(COMMAND ${program} --print-parameters
    OUTPUT_VARIABLE printed RESULT_VARIABLE status)
  string(REPLACE ";" "<semicolon>" printed "${printed}")
  string(REPLACE "\n" ";" lines "${printed}")
  set(path "")
  set(result "")
  foreach(line ${lines})
    string(STRIP "${line}" line)
    if(line MATCHES "^subsection (.*)$")
      list(APPEND path "${CMAKE_MATCH_1}")
    elseif(line STREQUAL "end")
      list(POP_BACK path)
    elseif(line MATCHES "^set ([^=]*[^ =]) *= *(.*)$")
      string(REPLACE ";" "/" prefix "${path}")
      list(APPEND result "${prefix}/${CMAKE_MATCH_1}")
    endif()
  endforeach()
  list(SORT result)
  set(${variable} "${result}" PARENT_SCOPE)
endfunction()
entries(${tree}/contact core_entries)
entries(${FULL} full_entries)
if(core_entries STREQUAL full_entries)
  string(APPEND report "Its entries are the full build's: yes\n")
else()
  set(only_core ${core_entries})
  list(REMOVE_ITEM only_core ${full_entries})
  set(only_full ${full_entries})
  list(REMOVE_ITEM only_full ${core_entries})
  string(APPEND report "Its entries are the full build's: no\n"
    "only in the core's: ${only_core}\nonly in the full build's: ${only_full}\n")
endif()

message(STATUS "${report}")
file(READ ${EXPECTED} expected)
if(NOT report STREQUAL expected)
  file(WRITE ${tree}/core_alone.output.new "${report}")
  message(FATAL_ERROR "Expected:\n${expected}\nGot (also in "
    "${tree}/core_alone.output.new):\n${report}")
endif()
