# gs_embed_shaders(<target> FUNCTION <c++ function name> ROOT <dir> FILES <files...>)
#
# Embeds GLSL files into <target> at build time. The generated translation unit defines
# `std::span<const engine::EmbeddedShaderFile> <function>()`, whose entries are named by their path
# relative to ROOT (the name `#include` directives use). Editing a GLSL file re-runs the generator.
set(GS_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedShadersScript.cmake)

function(gs_embed_shaders target)
  cmake_parse_arguments(ARG "" "FUNCTION;ROOT" "FILES" ${ARGN})
  set(output ${CMAKE_CURRENT_BINARY_DIR}/${ARG_FUNCTION}.cpp)
  set(absolute_files)
  foreach(file IN LISTS ARG_FILES)
    list(APPEND absolute_files ${ARG_ROOT}/${file})
  endforeach()
  string(REPLACE ";" "|" file_arg "${ARG_FILES}")
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DROOT=${ARG_ROOT} "-DFILES=${file_arg}"
            -DFUNCTION=${ARG_FUNCTION} -P ${GS_EMBED_SCRIPT}
    DEPENDS ${absolute_files} ${GS_EMBED_SCRIPT}
    COMMENT "Embedding shaders for ${target}"
    VERBATIM)
  target_sources(${target} PRIVATE ${output})
endfunction()
