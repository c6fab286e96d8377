# Writes OUT: a C++ file holding harness/export/player.c (IN) as a string,
# for export/export_c.h's exportPlayerSource(). Run by the build, never by hand.
file(READ ${IN} text)
set(body "// Generated from harness/export/player.c by tools/embed_player.cmake. Do not edit.\n#include \"export/export_c.h\"\nnamespace rayspec {\nconst std::string& exportPlayerSource() {\n  static const std::string text = R\"rayspec_player(${text})rayspec_player\";\n  return text;\n}\n}  // namespace rayspec\n")
file(WRITE ${OUT}.tmp "${body}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.tmp ${OUT})
