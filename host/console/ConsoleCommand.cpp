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
         "stop                 stop the robot\n"
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
         "wait explored|goal [SECONDS]   wait until exploring ends / the goal is reached\n"
         "help                 this list\n"
         "quit                 leave (the robot keeps its last command)\n";
}

ConsoleCommand parseConsoleCommand(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string t; in >> t;) w.push_back(t);
  ConsoleCommand c;
  if (w.empty() || w[0][0] == '#') return c;
  const std::string& k = w[0];
  if (k == "explore") {
    expectArgs(w, 1, "explore");
    c.kind = ConsoleCommand::Kind::Explore;
  } else if (k == "stop") {
    expectArgs(w, 1, "stop");
    c.kind = ConsoleCommand::Kind::Stop;
  } else if (k == "goto") {
    if (w.size() == 3 && w[1] == "near") {
      c.kind = ConsoleCommand::Kind::GotoNear;
      c.name = w[2];
    } else {
      expectArgs(w, 3, "goto C R  or  goto near LABEL");
      c.kind = ConsoleCommand::Kind::Goto;
      c.col = parseCell(w[1], "column");
      c.row = parseCell(w[2], "row");
    }
  } else if (k == "label") {
    expectArgs(w, 4, "label NAME C R");
    c.kind = ConsoleCommand::Kind::Label;
    c.name = w[1];
    c.col = parseCell(w[2], "column");
    c.row = parseCell(w[3], "row");
  } else if (k == "rooms") {
    expectArgs(w, 1, "rooms");
    c.kind = ConsoleCommand::Kind::Rooms;
  } else if (k == "route") {
    c.kind = ConsoleCommand::Kind::Route;
    if (w.size() == 3 && w[1] == "near") {
      c.near = true;
      c.name = w[2];
    } else {
      expectArgs(w, 4, "route ROOM C R  or  route near LABEL");
      c.name = w[1];
      c.col = parseCell(w[2], "column");
      c.row = parseCell(w[3], "row");
    }
  } else if (k == "save") {
    expectArgs(w, 2, "save DIR  or  save FILE.yaml");
    c.kind = ConsoleCommand::Kind::Save;
    c.name = w[1];
  } else if (k == "export") {
    expectArgs(w, 2, "export FILE.png");
    c.kind = ConsoleCommand::Kind::Export;
    c.name = w[1];
    if (c.name.size() < 5 || c.name.substr(c.name.size() - 4) != ".png")
      throw ConsoleError("export needs a .png file name: export FILE.png");
  } else if (k == "status") {
    expectArgs(w, 1, "status");
    c.kind = ConsoleCommand::Kind::Status;
  } else if (k == "battery") {
    expectArgs(w, 1, "battery");
    c.kind = ConsoleCommand::Kind::Battery;
  } else if (k == "map") {
    expectArgs(w, 1, "map");
    c.kind = ConsoleCommand::Kind::Map;
  } else if (k == "wait") {
    if (w.size() < 2 || w.size() > 3 || (w[1] != "explored" && w[1] != "goal"))
      throw ConsoleError("usage: wait explored|goal [SECONDS]");
    c.kind = ConsoleCommand::Kind::Wait;
    c.name = w[1];
    c.seconds = 600;
    if (w.size() == 3) {
      c.seconds = parseWhole(w[2], "wait: SECONDS", "a whole number of seconds");
      if (c.seconds < 1) throw ConsoleError("wait: SECONDS must be at least 1");
    }
  } else if (k == "help" || k == "?") {
    c.kind = ConsoleCommand::Kind::Help;
  } else if (k == "quit" || k == "exit") {
    c.kind = ConsoleCommand::Kind::Quit;
  } else {
    throw ConsoleError("unknown command '" + k + "' (type help for the list)");
  }
  return c;
}

}  // namespace nxtmap::console
