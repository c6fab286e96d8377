# Writes OUT: a C++ file holding every DIR/*.glsl as a string, for
# harness/glsl/embedded_shaders.h. Run by the build, never by hand.
file(GLOB files ${DIR}/*.glsl)
list(SORT files)
set(body "// Generated from shaders/*.glsl by tools/embed_shaders.cmake. Do not edit.\n#include \"glsl/embedded_shaders.h\"\nnamespace rayspec {\nconst std::map<std::string, std::string>& embeddedShaders() {\n  static const std::map<std::string, std::string> shaders = {\n")
foreach(f ${files})
  get_filename_component(name ${f} NAME)
  file(READ ${f} text)
  string(APPEND body "    {\"${name}\", R\"rayspec_glsl(${text})rayspec_glsl\"},\n")
endforeach()
string(APPEND body "  };\n  return shaders;\n}\n}  // namespace rayspec\n")
file(WRITE ${OUT}.tmp "${body}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.tmp ${OUT})
