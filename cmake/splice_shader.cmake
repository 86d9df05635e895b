# Builds a built-in shader from its template: the template's "// @include lighting.glsl" line
# becomes the text of shaders/lighting.glsl, so the program a student opens is whole.
# cmake -DTEMPLATE=phong.frag.in -DPART=lighting.glsl -DOUTPUT=phong.frag -P splice_shader.cmake
file(READ "${TEMPLATE}" text)
file(READ "${PART}" part)
set(marker "// @include lighting.glsl\n")
string(FIND "${text}" "${marker}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${TEMPLATE} has no '// @include lighting.glsl' line")
endif()
string(REPLACE "${marker}" "${part}" text "${text}")
file(WRITE "${OUTPUT}" "${text}")
