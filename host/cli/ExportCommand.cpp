#include "host/cli/ExportCommand.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "host/cli/Errors.hpp"
#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/network/HouseFiles.hpp"
#include "host/report/MapImage.hpp"

namespace nxtmap::cli {
namespace {

// Gateway cells in the house frame.
std::vector<Cell> gatewayCells(const network::HouseNetwork& h) {
  std::vector<Cell> out;
  for (const network::Gateway& g : h.gateways()) {
    const network::RoomNode& a = h.rooms()[static_cast<size_t>(g.roomA)];
    for (const Cell c : g.cellsA) out.push_back(a.toHouse.apply(c));
  }
  return out;
}

void writePngFile(const network::HouseNetwork& h, const network::RoomMap& m, int px, const std::string& path) {
  report::RgbImage img;
  img.width = std::max(1, m.width() * px);
  img.height = std::max(1, m.height() * px);
  img.rgb.assign(static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 3, 160);
  for (int row = 0; row < m.height(); ++row) {
    for (int col = 0; col < m.width(); ++col) {
      const CellState s = m.at(network::mapCellToRoom(m, col, row));
      if (s == CellState::Free) img.fill(col * px, row * px, px, px, 255, 255, 255);
      if (s == CellState::Occupied) img.fill(col * px, row * px, px, px, 0, 0, 0);
    }
  }
  for (const Cell c : gatewayCells(h)) {
    int col, row;
    network::roomCellToMap(m, c, col, row);
    if (m.inside(c)) img.fill(col * px, row * px, px, px, 40, 170, 60);
  }
  std::string error;
  if (!report::writePng(path, img, error)) throw CliError(error);
}

void writeSvgFile(const network::HouseNetwork& h, const network::RoomMap& m, const std::string& path) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << m.width() << " " << m.height() << "\" width=\""
    << m.width() * 6 << "\" height=\"" << m.height() * 6 << "\" shape-rendering=\"crispEdges\">\n"
    << "<rect width=\"" << m.width() << "\" height=\"" << m.height() << "\" fill=\"#a0a0a0\"/>\n";
  for (int row = 0; row < m.height(); ++row) {  // one rectangle per run of equal known cells
    int col = 0;
    while (col < m.width()) {
      const CellState s = m.at(network::mapCellToRoom(m, col, row));
      int end = col + 1;
      while (end < m.width() && m.at(network::mapCellToRoom(m, end, row)) == s) ++end;
      if (s != CellState::Unknown) {
        o << "<rect x=\"" << col << "\" y=\"" << row << "\" width=\"" << end - col << "\" height=\"1\" fill=\""
          << (s == CellState::Free ? "#ffffff" : "#000000") << "\"/>\n";
      }
      col = end;
    }
  }
  for (const Cell c : gatewayCells(h)) {
    int col, row;
    network::roomCellToMap(m, c, col, row);
    o << "<rect class=\"gateway\" x=\"" << col << "\" y=\"" << row
      << "\" width=\"1\" height=\"1\" fill=\"#28aa3c\"/>\n";
  }
  for (const network::RoomNode& r : h.rooms()) {
    int col, row;
    network::roomCellToMap(m, r.toHouse.apply(Cell{0, 0}), col, row);
    o << "<text x=\"" << col << "\" y=\"" << row << "\" font-size=\"3\" fill=\"#c03030\">" << r.name << "</text>\n";
  }
  o << "</svg>\n";
  std::string error;
  if (!fileio::writeFileAtomically(path, o.str(), error)) throw CliError(error);
}

}  // namespace

CLI::App* addExportCommand(CLI::App& app, ExportOptions& o) {
  CLI::App* c = app.add_subcommand("export", "the merged map of a saved house as PNG, SVG or one ROS map");
  c->add_option("house", o.house, "house directory (written by sim-house --save)")->required();
  c->add_option("--png", o.png, "write a PNG picture (free white, unknown grey, walls black, gateways green)");
  c->add_option("--svg", o.svg, "write an SVG drawing of the same");
  c->add_option("--ros", o.ros, "write merged.yaml + merged.pgm (ROS map_server) into this directory");
  c->add_option("--cell-px", o.cellPx, "PNG pixels per cell, 1..32 (default 4)");
  return c;
}

int runExport(const ExportOptions& o) {
  if (o.png.empty() && o.svg.empty() && o.ros.empty()) {
    throw CliError("export: give at least one of --png FILE, --svg FILE, --ros DIR");
  }
  if (o.cellPx < 1 || o.cellPx > 32) throw CliError("--cell-px must lie in 1..32, not " + std::to_string(o.cellPx));
  const network::HouseLoad l = network::loadHouse(o.house);
  if (!l.network) throw CliError(l.error);
  const network::HouseNetwork& h = *l.network;
  std::string outputError;  // both files are checked before either is written
  for (const std::string& out : {o.png, o.svg}) {
    if (!out.empty() && !fileio::resolveOutputTarget(out, outputError)) throw CliError(outputError);
  }
  const network::RoomMap merged = h.merged();
  constexpr long kMaxPngPixels = 8192L * 8192;  // the picture's RGB buffer stays within 192 MiB
  if (!o.png.empty() && static_cast<long>(merged.width()) * merged.height() * o.cellPx * o.cellPx > kMaxPngPixels) {
    throw CliError("export: the house is " + std::to_string(merged.width()) + " x " + std::to_string(merged.height()) +
                   " cells; at --cell-px " + std::to_string(o.cellPx) + " its picture would hold more than " +
                   std::to_string(kMaxPngPixels) + " pixels: give a smaller --cell-px");
  }
  if (!o.png.empty()) {
    writePngFile(h, merged, o.cellPx, o.png);
    std::cout << "wrote " << o.png << "\n";
  }
  if (!o.svg.empty()) {
    writeSvgFile(h, merged, o.svg);
    std::cout << "wrote " << o.svg << "\n";
  }
  if (!o.ros.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.ros, ec);
    mapio::OccupancyMap m = network::toOccupancyMap(merged, l.resolutionM);
    for (const network::RoomNode& r : h.rooms()) {  // labels in the house frame
      for (const auto& [name, cell] : r.labels) {
        int col, row;
        network::roomCellToMap(merged, r.toHouse.apply(cell), col, row);
        const std::string label = m.labels().count(name) ? r.name + "_" + name : name;
        m.setLabel(label, mapio::CellBlock{col, row, 1, 1});
      }
    }
    const std::string yaml = (std::filesystem::path(o.ros) / "merged.yaml").string();
    std::string error;
    if (!mapio::saveRosMap(m, yaml, error)) throw CliError(error);
    std::cout << "wrote " << yaml << "\n";
  }
  return kExitOk;
}

}  // namespace nxtmap::cli
