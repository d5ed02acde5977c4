# Compiles data files into a C++ source as string views, looked up by their path relative to
# the data folder (models/core/embedded_data.h). The generator reruns when a file changes.
function(clearsky_embed_data output data_root)
  set(files ${ARGN})
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DDATA_ROOT=${data_root}
            "-DFILES=${files}" -P ${PROJECT_SOURCE_DIR}/cmake/EmbedDataScript.cmake
    DEPENDS ${files} ${PROJECT_SOURCE_DIR}/cmake/EmbedDataScript.cmake
    COMMENT "Embedding physical tables from ${data_root}"
    VERBATIM)
endfunction()
