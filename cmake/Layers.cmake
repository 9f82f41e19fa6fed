# Layering: app -> runner -> render -> scenarios -> {trap, metrics} -> engine -> Bullet.
#
# Each layer is one library target whose include directory holds links to its own folder and to
# the folders of the layers it may use, and nothing else. An include that points the wrong way
# (engine including scenarios/...) therefore fails to compile instead of passing silently.
function(rodsort_layer name)
  cmake_parse_arguments(LAYER "" "" "USES;LIBS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  # A layer that has no sources yet is a header-only interface library.
  if(sources)
    add_library(rodsort_${name} STATIC ${sources})
    set(scope PUBLIC)
  else()
    add_library(rodsort_${name} INTERFACE)
    set(scope INTERFACE)
  endif()
  set(include_root ${PROJECT_BINARY_DIR}/layer_include/${name})
  file(MAKE_DIRECTORY ${include_root})
  foreach(visible IN LISTS LAYER_USES ITEMS ${name})
    if(NOT EXISTS ${include_root}/${visible})
      file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${visible} ${include_root}/${visible} SYMBOLIC)
    endif()
  endforeach()
  target_include_directories(rodsort_${name} ${scope} ${include_root})
  foreach(used IN LISTS LAYER_USES)
    target_link_libraries(rodsort_${name} ${scope} rodsort_${used})
  endforeach()
  target_link_libraries(rodsort_${name} ${scope} ${LAYER_LIBS})
endfunction()

# One Catch2 executable per layer, built from tests/<layer>/*_test.cpp, registered with CTest.
function(rodsort_layer_tests name)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*_test.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(${name}_tests ${sources} ${CMAKE_CURRENT_SOURCE_DIR}/test_main.cpp)
  target_link_libraries(${name}_tests PRIVATE rodsort_${name} Catch2::Catch2)
  target_include_directories(${name}_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_definitions(${name}_tests PRIVATE
    RODSORT_SOURCE_DIR="${PROJECT_SOURCE_DIR}" RODSORT_BINARY_DIR="${PROJECT_BINARY_DIR}")
  # --warn NoTests: a name CTest cannot pass back to Catch (a ";" splits it) fails instead of
  # running nothing and passing.
  # The longest test, a golden sorting run, takes some 200 s on 2 cores here and was seen to take
  # four times as long on a slower machine: the limit leaves room for that, and still ends a hang.
  catch_discover_tests(${name}_tests TEST_PREFIX "${name}: " EXTRA_ARGS --warn NoTests
                       PROPERTIES TIMEOUT 1500
                       ENVIRONMENT "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/lsan.supp")
endfunction()
