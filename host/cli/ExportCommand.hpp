// `nxtmap export HOUSE [--png FILE] [--svg FILE] [--ros DIR]`: the merged map of a saved house
// (house frame) as a picture, a vector drawing, or one ROS map_server map (merged.yaml + .pgm).
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct ExportOptions {
  std::string house;  // a house directory (nxtmap sim-house --save)
  std::string png;
  std::string svg;
  std::string ros;  // directory for merged.yaml + merged.pgm
  int cellPx = 4;   // PNG pixels per cell
};

CLI::App* addExportCommand(CLI::App& app, ExportOptions& options);
int runExport(const ExportOptions& options);

}  // namespace nxtmap::cli
