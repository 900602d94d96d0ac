/// @file main.cpp
/// @brief fuzzyfeed (work in progress).
#include "cli/tool_app.hpp"

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("fuzzyfeed", "work in progress");
  return tool.run(argc, argv, [] {});
}
