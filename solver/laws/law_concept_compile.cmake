# cmake -P script behind ctest law_concept_compile: compiles solver/laws/law_concept_compile.cc once per
# bad member (-fsyntax-only) and checks that the first line saying "error" names the member.
# Variables: CXX (the compiler), SOURCE (law_concept_compile.cc), ROOT (the source tree),
# INCLUDES (;-list of include directories), FLAGS (;-list, e.g. -std=c++20), THROUGH (0: the
# cases that the concept's assert alone decides, a second each; 1: the cases that need the
# 50-digit scalar, through ivv::simulate, which compiles every integrator: ~9 s of CPU each).
cmake_policy(SET CMP0007 NEW)
set(args ${FLAGS} -fsyntax-only -I${ROOT})
foreach(dir IN LISTS INCLUDES)
  list(APPEND args -I${dir})
endforeach()

# member number, the name its first error line must contain ("-": the law must compile: the
# good law, and laws that leave out an optional member), through simulate() (1) or the
# concept's assert alone (0)
set(cases
  "0;-;0" "1;`name`;0" "2;`rate_dependent`;0" "3;`force(h, z, v)`;0" "4;`stiffness(h, z, v)`;0"
  "5;`rate_stiffness(h, z, v)`;0" "7;-;0" "8;-;0" "12;-;0" "9;`stored_energy(h, z)`;0"
  "11;`hysteresis_work(h)`;0" "10;`hysteresis_work(h)`;1" "6;`segment_end(h)`;1")
set(failures "")
set(i 0)
list(LENGTH cases n)
while(i LESS n)
  list(GET cases ${i} member)
  math(EXPR j "${i} + 1")
  list(GET cases ${j} expected)
  math(EXPR k "${i} + 2")
  list(GET cases ${k} through)
  math(EXPR i "${i} + 3")
  if(NOT through EQUAL THROUGH)
    continue()
  endif()
  execute_process(COMMAND ${CXX} ${args} -DIVV_BAD_MEMBER=${member}
                          -DIVV_THROUGH_SIMULATE=${through} ${SOURCE}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(what "member ${member} (through simulate: ${through})")
  if(expected STREQUAL "-")
    if(NOT rc EQUAL 0)
      string(APPEND failures "${what}: the law must compile, but does not:\n${err}\n")
    endif()
    continue()
  endif()
  if(rc EQUAL 0)
    string(APPEND failures "${what}: compiled, but must fail naming ${expected}\n")
    continue()
  endif()
  string(REGEX MATCH "[^\n]*error:[^\n]*" first "${err}")
  string(FIND "${first}" "${expected}" at)
  if(at EQUAL -1)
    string(APPEND failures "${what}: first error line does not name ${expected}:\n  ${first}\n")
  else()
    message(STATUS "${what}: ${first}")
  endif()
endwhile()
if(failures)
  message(FATAL_ERROR "${failures}")
endif()
