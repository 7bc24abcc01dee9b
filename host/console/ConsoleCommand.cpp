#include "host/console/ConsoleCommand.hpp"

#include <cctype>
#include <sstream>
#include <vector>

namespace nxtmap::console {
namespace {

// A whole number of at most 5 digits (0-99999): `what` names the field and `unit` what it counts.
int parseWhole(const std::string& s, const char* what, const char* unit) {
  const std::string wrong = std::string(what) + " '" + s + "' is not " + unit;
  if (s.empty() || s.size() > 5) throw ConsoleError(wrong);
  for (char c : s) {
    if (!std::isdigit(static_cast<unsigned char>(c))) throw ConsoleError(wrong + " (0, 1, 2, ...)");
  }
  return std::stoi(s);
}

int parseCell(const std::string& s, const char* what) { return parseWhole(s, what, "a cell number"); }

void expectArgs(const std::vector<std::string>& w, size_t n, const char* form) {
  if (w.size() != n) throw ConsoleError(std::string("usage: ") + form);
}

}  // namespace

const char* consoleHelp() {
  return "explore              start (or resume) exploring\n"
         "explore house        map the whole house by itself: room by room, through every exit (the\n"
         "                     start is labelled 'start')\n"
         "stop                 stop the robot\n"
         "calibrate [SECONDS]  measure the turns' error against the walls where the robot stands (a sweep,\n"
         "                     four whole turns, a sweep), wait for it (default 300 s); the brick keeps it\n"
         "goto C R             drive to map cell column C, row R (as the map shows them)\n"
         "goto near LABEL      drive next to a labelled cell\n"
         "label NAME C R       name a map cell\n"
         "rooms                the house's rooms (the current one marked), their exits and labels\n"
         "route ROOM C R       drive to cell column C, row R of another room's map (ROOM: number or name),\n"
         "                     through the gateways between rooms\n"
         "route near LABEL     drive next to a labelled cell, in whichever room has it\n"
         "save DIR             save the house (house.yaml + one ROS map per room, labels kept)\n"
         "save FILE.yaml       save the current room's map (ROS map_server YAML + PGM, labels kept)\n"
         "export FILE.png      picture of the map\n"
         "status               link, robot and map figures\n"
         "battery              the brick's battery voltage\n"
         "map                  print the map\n"
         "wait explored|goal|house [SECONDS]   wait until exploring ends / the goal is reached /\n"
         "                     the house is mapped\n"
         "help                 this list\n"
         "quit                 leave (the robot keeps its last command)\n";
}

namespace {

using Words = std::vector<std::string>;
using K = ConsoleCommand::Kind;

// A command without arguments.
template <K kind>
void parseBare(const Words& w, ConsoleCommand& c) {
  expectArgs(w, 1, w[0].c_str());
  c.kind = kind;
}

void parseGoto(const Words& w, ConsoleCommand& c) {
  if (w.size() == 3 && w[1] == "near") {
    c.kind = K::GotoNear;
    c.name = w[2];
    return;
  }
  expectArgs(w, 3, "goto C R  or  goto near LABEL");
  c.kind = K::Goto;
  c.col = parseCell(w[1], "column");
  c.row = parseCell(w[2], "row");
}

void parseLabel(const Words& w, ConsoleCommand& c) {
  expectArgs(w, 4, "label NAME C R");
  c.kind = K::Label;
  c.name = w[1];
  c.col = parseCell(w[2], "column");
  c.row = parseCell(w[3], "row");
}

void parseRoute(const Words& w, ConsoleCommand& c) {
  c.kind = K::Route;
  if (w.size() == 3 && w[1] == "near") {
    c.near = true;
    c.name = w[2];
    return;
  }
  expectArgs(w, 4, "route ROOM C R  or  route near LABEL");
  c.name = w[1];
  c.col = parseCell(w[2], "column");
  c.row = parseCell(w[3], "row");
}

void parseSave(const Words& w, ConsoleCommand& c) {
  expectArgs(w, 2, "save DIR  or  save FILE.yaml");
  c.kind = K::Save;
  c.name = w[1];
}

void parseExport(const Words& w, ConsoleCommand& c) {
  expectArgs(w, 2, "export FILE.png");
  c.kind = K::Export;
  c.name = w[1];
  if (c.name.size() < 5 || c.name.substr(c.name.size() - 4) != ".png")
    throw ConsoleError("export needs a .png file name: export FILE.png");
}

void parseCalibrate(const Words& w, ConsoleCommand& c) {
  if (w.size() > 2) throw ConsoleError("usage: calibrate [SECONDS]");
  c.kind = K::Calibrate;
  c.seconds = 300;
  if (w.size() == 2) {
    c.seconds = parseWhole(w[1], "calibrate: SECONDS", "a whole number of seconds");
    if (c.seconds < 1) throw ConsoleError("calibrate: SECONDS must be at least 1");
  }
}

void parseWait(const Words& w, ConsoleCommand& c) {
  if (w.size() < 2 || w.size() > 3 || (w[1] != "explored" && w[1] != "goal" && w[1] != "house"))
    throw ConsoleError("usage: wait explored|goal|house [SECONDS]");
  c.kind = K::Wait;
  c.name = w[1];
  c.seconds = 600;
  if (w.size() == 3) {
    c.seconds = parseWhole(w[2], "wait: SECONDS", "a whole number of seconds");
    if (c.seconds < 1) throw ConsoleError("wait: SECONDS must be at least 1");
  }
}

void parseExplore(const Words& w, ConsoleCommand& c) {
  if (w.size() == 2 && w[1] == "house") {
    c.kind = K::ExploreHouse;
    return;
  }
  expectArgs(w, 1, "explore  or  explore house");
  c.kind = K::Explore;
}

// Any words after the command are ignored.
template <K kind>
void parseLoose(const Words&, ConsoleCommand& c) {
  c.kind = kind;
}

// The first word of a line and its parser.
struct Syntax {
  const char* word;
  void (*parse)(const Words&, ConsoleCommand&);
};
const Syntax kSyntax[] = {
    {"explore", parseExplore},
    {"stop", parseBare<K::Stop>},
    {"calibrate", parseCalibrate},
    {"goto", parseGoto},
    {"label", parseLabel},
    {"rooms", parseBare<K::Rooms>},
    {"route", parseRoute},
    {"save", parseSave},
    {"export", parseExport},
    {"status", parseBare<K::Status>},
    {"battery", parseBare<K::Battery>},
    {"map", parseBare<K::Map>},
    {"wait", parseWait},
    {"help", parseLoose<K::Help>},
    {"?", parseLoose<K::Help>},
    {"quit", parseLoose<K::Quit>},
    {"exit", parseLoose<K::Quit>},
};

}  // namespace

ConsoleCommand parseConsoleCommand(const std::string& line) {
  std::istringstream in(line);
  Words w;
  for (std::string t; in >> t;) w.push_back(t);
  ConsoleCommand c;
  if (w.empty() || w[0][0] == '#') return c;
  for (const Syntax& s : kSyntax) {
    if (w[0] != s.word) continue;
    s.parse(w, c);
    return c;
  }
  throw ConsoleError("unknown command '" + w[0] + "' (type help for the list)");
}

}  // namespace nxtmap::console
