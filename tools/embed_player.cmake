# Writes OUT: a C++ file holding the player of an exported reproducer, the
# files of harness/export/player/ (DIR) joined in the order of its parts.cmake,
# as one string for export/export_c.h's exportPlayerSource(). Run by the
# build, never by hand.
include(${DIR}/parts.cmake)
# One blank line between two parts (each ends with one newline, as
# clang-format leaves a C file).
set(text "")
foreach(part ${RAYSPEC_PLAYER_PARTS})
  file(READ ${DIR}/${part} part_text)
  if(NOT text STREQUAL "")
    string(APPEND text "\n")
  endif()
  string(APPEND text "${part_text}")
endforeach()
set(body "// Generated from harness/export/player/ by tools/embed_player.cmake. Do not edit.\n#include \"export/export_c.h\"\nnamespace rayspec {\nconst std::string& exportPlayerSource() {\n  static const std::string text = R\"rayspec_player(${text})rayspec_player\";\n  return text;\n}\n}  // namespace rayspec\n")
file(WRITE ${OUT}.tmp "${body}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.tmp ${OUT})
