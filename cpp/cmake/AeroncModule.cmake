# aeronc_module(NAME [DEPENDS module...] [PUBLIC_LIBS target...] [PRIVATE_LIBS target...])
#
# One C++ module, one static library aeronc_<NAME>: the sources cpp/src/<NAME>/*.cpp (a new
# file there is picked up by the next build) and the public headers cpp/include/aeronc/<NAME>/.
# DEPENDS names the modules whose headers it includes; they are linked PUBLIC and must be
# declared before it, so the module graph cannot have a cycle. PUBLIC_LIBS are the third-party
# targets its public headers need, PRIVATE_LIBS those only its sources need.
#
# Every include dir is cpp/include, so the compiler alone would let a module include any
# other's headers: CheckModuleIncludes.cmake fails the build (target aeronc_module_check) and
# the test module_includes when a module includes <aeronc/X/...> without depending on X.
set(AERONC_MODULE_CHECK ${CMAKE_CURRENT_LIST_DIR}/CheckModuleIncludes.cmake)
set(AERONC_MODULE_GRAPH_FILE ${CMAKE_BINARY_DIR}/aeronc_modules.txt)
add_custom_target(aeronc_module_check
  COMMAND ${CMAKE_COMMAND} -DCPP_DIR=${CMAKE_CURRENT_SOURCE_DIR} -DGRAPH=${AERONC_MODULE_GRAPH_FILE}
          -P ${AERONC_MODULE_CHECK}
  COMMENT "Checking the includes of the C++ modules against their declared dependencies")

function(aeronc_module name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "DEPENDS;PUBLIC_LIBS;PRIVATE_LIBS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "aeronc_module(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  set(deps)
  foreach(d IN LISTS arg_DEPENDS)
    if(NOT TARGET aeronc_${d})
      message(FATAL_ERROR "aeronc_module(${name}): module ${d} is not declared yet; declare it first")
    endif()
    list(APPEND deps aeronc_${d})
  endforeach()
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/${name}/*.cpp)
  if(NOT sources)
    message(FATAL_ERROR "aeronc_module(${name}): no sources in ${CMAKE_CURRENT_SOURCE_DIR}/src/${name}")
  endif()
  add_library(aeronc_${name} STATIC ${sources})
  target_include_directories(aeronc_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(aeronc_${name} PUBLIC ${deps} ${arg_PUBLIC_LIBS} PRIVATE ${arg_PRIVATE_LIBS})
  target_compile_options(aeronc_${name} PRIVATE -Wall -Wextra -Wno-unused-parameter)
  add_dependencies(aeronc_${name} aeronc_module_check)
  list(JOIN arg_DEPENDS " " line)
  set_property(GLOBAL APPEND PROPERTY AERONC_MODULE_GRAPH "${name}: ${line}")
endfunction()

# Writes the declared graph, one "name: dep dep" line per module, for the check.
function(aeronc_write_module_graph)
  get_property(graph GLOBAL PROPERTY AERONC_MODULE_GRAPH)
  list(JOIN graph "\n" text)
  file(WRITE ${AERONC_MODULE_GRAPH_FILE} "${text}\n")
endfunction()
