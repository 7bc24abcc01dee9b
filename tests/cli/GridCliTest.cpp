// --grid from the outside: the room grid of sim, experiments and connect sim: (the brick's 64 x 64
// cells unless chosen). A 90 x 20-cell corridor of 10 cm cells (written here) is longer than the
// brick's grid: the run maps it up to the grid's edge and says so; 128 cells map it whole.
#include "tests/cli/CliTestSupport.hpp"

#include <gtest/gtest.h>

namespace nxtmap::cli::test {
namespace {

// A Moving AI map of width x height cells, walled all round, free inside.
std::string walledRoom(int width, int height) {
  std::string text = "type octile\nheight " + std::to_string(height) + "\nwidth " + std::to_string(width) + "\nmap\n";
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) text += (x == 0 || y == 0 || x == width - 1 || y == height - 1) ? '@' : '.';
    text += '\n';
  }
  return text;
}

std::string field(const std::string& out, const std::string& label) {
  const size_t at = out.find("\n" + label);
  if (at == std::string::npos) return "";
  return out.substr(at + 1, out.find('\n', at + 1) - at - 1);
}

bool has(const std::string& text, const std::string& needle) { return text.find(needle) != std::string::npos; }

const std::string kNote = "the room is larger than the ";

TEST(GridCli, ACorridorLongerThanTheGridIsMappedToItsEdgeAndSaysSo) {
  TempDir d("grid-sim");
  const std::string corridor = d.write("corridor.map", walledRoom(90, 20));
  struct Case {
    std::string grid, strategy;
    std::string end;   // the "end" line's start
    bool note;         // the grid-edge line is printed
    std::string says;  // in the run line
  };
  const Case cases[] = {
      {"", "propagation", "end              complete (up to the grid's edge)", true, ""},
      {"64", "propagation", "end              complete (up to the grid's edge)", true, ""},
      {"64", "frontier", "end              complete (up to the grid's edge)", true, ""},
      {"128", "propagation", "end              complete", false, ", grid 128 x 128 cells"},
      {"128", "frontier", "end              complete", false, ", grid 128 x 128 cells"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE("--grid '" + c.grid + "' " + c.strategy);
    const std::string png = d.path("map-" + c.grid + c.strategy + ".png");
    const RunOutput r = runCli("sim " + shellQuote(corridor) + " --start 2,10 --show none --strategy " + c.strategy +
                               (c.grid.empty() ? "" : " --grid " + c.grid) + " --png " + shellQuote(png));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(field(r.out, "end"), c.end) << r.out;
    EXPECT_EQ(has(r.out, kNote), c.note) << r.out;
    if (c.note) {
      EXPECT_TRUE(has(r.out,
                      "\nthe room is larger than the 64 x 64-cell grid (6.4 m at 10 cm cells): mapped up to "
                      "its edge; --grid 128 maps it whole\n"))
          << r.out;
    }
    if (c.says.empty()) {
      EXPECT_FALSE(has(field(r.out, "run"), ", grid ")) << r.out;  // the brick's grid goes without saying
    } else {
      EXPECT_TRUE(has(field(r.out, "run"), c.says)) << r.out;
    }
    EXPECT_TRUE(has(r.out, "wrote " + png)) << r.out;  // the outputs are written all the same
    EXPECT_FALSE(readFile(png).empty());
  }
}

TEST(GridCli, ARoomThatFitsEveryGridMapsTheSameOnEach) {
  TempDir d("grid-small");
  const std::string room = d.write("small.map", walledRoom(12, 10));
  std::string first;
  for (const std::string grid : {"16", "32", "64", "128"}) {
    SCOPED_TRACE(grid);
    const RunOutput r = runCli("sim " + shellQuote(room) + " --start 3,3 --show none --grid " + grid);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(field(r.out, "end"), "end              complete") << r.out;
    EXPECT_FALSE(has(r.out, kNote)) << r.out;
    const std::string figures = r.out.substr(r.out.find("\nend"));
    if (first.empty()) first = figures;
    EXPECT_EQ(figures, first);  // the grid's size changes nothing while the room fits
  }
}

TEST(GridCli, ExperimentsCountTheRunsThatMetTheGridsEdge) {
  TempDir d("grid-experiments");
  d.write("corridor.map", walledRoom(90, 20));
  d.write("small.map", walledRoom(12, 10));
  d.write("scenarios.tsv",
          "# id\tmap\tstart_col\tstart_row\tseed_x_m\tseed_z_m\toccupied_cells\tseed_unknowns\tseed_time_units\t"
          "seed_sensor_count\tseed_detected_pct\n"
          "corridor\tcorridor.map\t2\t10\t0\t0\t216\t0\t0\t0\t100\n"
          "small\tsmall.map\t3\t3\t0\t0\t40\t0\t0\t0\t100\n");
  struct Case {
    std::string options;
    std::string summary;  // empty: no grid-edge summary
    std::string header;   // in the header line (empty: no grid named)
  };
  const Case cases[] = {
      {"", "grid full: 2 of 4 runs met the grid's edge (corridor x2): " + kNote + "64 x 64-cell grid", ""},
      {"--grid 32 --strategy both",
       "grid full: 4 of 8 runs met the grid's edge (corridor x4): " + kNote +
           "32 x 32-cell grid (3.2 m at 10 cm cells): mapped up to its edge; --grid 128 maps it whole",
       ", grid 32 x 32 cells"},
      {"--grid 128", "", ", grid 128 x 128 cells"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.options);
    const RunOutput r = runCli("experiments " + shellQuote(d.path()) + " --seeds 2 " + c.options);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(has(r.out, "\ngrid full: "), !c.summary.empty()) << r.out;
    if (!c.summary.empty()) {
      EXPECT_TRUE(has(r.out, "\n" + c.summary)) << r.out;
    }
    const std::string header = lines(r.out).at(0);
    if (c.header.empty()) {
      EXPECT_FALSE(has(header, ", grid ")) << header;
    } else {
      EXPECT_TRUE(has(header, c.header)) << header;
    }
  }
}

TEST(GridCli, AGridOtherThanTheFourIsOneLineAndExitTwo) {
  TempDir d("grid-bad");
  const std::string room = d.write("small.map", walledRoom(12, 10));
  d.write("scenarios.tsv", "small\tsmall.map\t3\t3\t0\t0\t40\t0\t0\t0\t100\n");
  for (const std::string grid : {"48", "0", "8", "256", "-64", "64.0", "abc"}) {
    for (const std::string& command : std::vector<std::string>{
             "sim " + shellQuote(room) + " --start 3,3 --show none", "experiments " + shellQuote(d.path()),
             "connect " + shellQuote("sim:" + room + "@3,3") + " --connect-timeout 5"}) {
      SCOPED_TRACE(command + " --grid " + grid);
      const RunOutput r = runCli(command + " --grid " + grid, 60);
      EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
      EXPECT_TRUE(has(r.err, "--grid must be 16, 32, 64 (the brick's) or 128 cells per side")) << r.err;
      EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    }
  }
}

TEST(GridCli, ConnectTakesTheGridForSimLinksOnly) {
  TempDir d("grid-connect");
  const std::string room = d.write("small.map", walledRoom(12, 10));
  const RunOutput sim = runCli("connect " + shellQuote("sim:" + room + "@3,3") + " --grid 128 --connect-timeout 5", 60);
  EXPECT_EQ(sim.exitCode, 0) << sim.out << sim.err;
  EXPECT_TRUE(has(sim.out, "connected to sim:")) << sim.out;
  const RunOutput tcp = runCli("connect tcp:127.0.0.1:9 --grid 128 --connect-timeout 1", 60);
  EXPECT_EQ(tcp.exitCode, 2) << tcp.out << tcp.err;
  EXPECT_TRUE(has(tcp.err, "--grid")) << tcp.err;
  EXPECT_TRUE(has(tcp.err, "only apply to sim: links")) << tcp.err;
}

}  // namespace
}  // namespace nxtmap::cli::test
