# clearsky_layer(NAME DIR DEPENDENCIES...): a static library of every .cpp under DIR (an
# interface library while the layer has no sources yet), with the project root as include path.
# Precompiled headers (the layer's heaviest, most included headers) cut the clean build time,
# which CI pays twice (Release and sanitizers): clearsky_precompile(TARGET HEADERS...).
function(clearsky_precompile target)
  if(CLEARSKY_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

function(clearsky_layer name dir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  list(FILTER sources EXCLUDE REGEX ".*/server/main\\.cpp$")
  if(sources)
    add_library(${name} STATIC ${sources} ${CLEARSKY_LAYER_EXTRA_SOURCES})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${ARGN})
    target_link_libraries(${name} PRIVATE clearsky_warnings)
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARGN})
  endif()
endfunction()
