/// @file main.cpp
/// @brief tnorm-bench (work in progress).
#include "cli/tool_app.hpp"

int main(int argc, char** argv) {
  tk::cli::ToolApp tool("tnorm-bench", "work in progress");
  return tool.run(argc, argv, [] {});
}
