#include "host/cli/EmulateCommand.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "common/explore/Explorer.hpp"
#include "host/cli/Args.hpp"
#include "host/cli/EmulatedMapScore.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/LcdSeries.hpp"
#include "host/cli/RadioMirror.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/FlashState.hpp"
#include "host/emu/LinkServer.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::cli {
namespace {

// Why the firmware's explorer stopped (g_explorerEnd, ExplorerEnd), as words after "exploration done".
std::string endReason(const emu::EmulatedRun& run) {
  const std::optional<uint8_t> end = run.readSymbolByte("g_explorerEnd");
  if (!end) return "";
  switch (static_cast<ExplorerEnd>(*end)) {
    case ExplorerEnd::Complete: return ": nothing left to map within reach";
    case ExplorerEnd::GridFull: return ": the room outgrew the grid";
    case ExplorerEnd::ActionLimit: return ": the action limit was reached";
    case ExplorerEnd::Running: break;
  }
  return "";
}

// --flash-keep FILE before the run: the file is checked (readable if there, writable), and the pages above the
// image come from it. Returns the line that says what the brick finds kept.
std::string keepFlashFrom(const std::string& file, emu::ElfImage& image) {
  std::string error;
  if (!fileio::resolveOutputTarget(file, error)) throw CliError("--flash-keep: " + error);
  const std::optional<std::vector<uint8_t>> kept = emu::readFlashState(file, error);
  if (!error.empty()) throw CliError("--flash-keep: " + error);
  if (!kept) return "flash kept       " + file + ": new (the brick starts with nothing kept)\n";
  image.keepPagesFrom(*kept);
  const std::optional<WheelCalibration> w = emu::storedWheels(image.flash());
  return "flash kept       " + file + ": wheels " + (w ? emu::wheelsText(*w) : std::string("none kept")) + "\n";
}

// After the run: what the brick's flash holds of its wheels, and (with --score) what it last told the PC.
std::string wheelLines(const std::vector<uint8_t>& flash, const RadioMirror* mirror) {
  const std::optional<WheelCalibration> w = emu::storedWheels(flash);
  std::string lines = "wheels in flash  " + (w ? emu::wheelsText(*w) : std::string("none")) + "\n";
  if (mirror != nullptr && mirror->brickCounters()) {
    WheelCalibration told;
    told.driftUradPerM = mirror->brickCounters()->wheelDrift10UradPerM * 10;
    told.turnPpm = mirror->brickCounters()->wheelTurn10Ppm * 10;
    lines += "wheels reported  " + emu::wheelsText(told) + " (the brick's last counters over the radio)\n";
  }
  return lines;
}

}  // namespace

CLI::App* addEmulateCommand(CLI::App& app, EmulateOptions& o) {
  CLI::App* c = app.add_subcommand("emulate", "the firmware image in the emulated brick, driving the simulated robot");
  c->add_option("world", o.world,
                "world: Moving AI .map, ROS map_server .yaml, nxtmap world .yaml (worlds/rooms) or HouseExpo .json");
  c->add_option("--start", o.start,
                "start cell COL,ROW of a raster world (col right, row down from the top-left); for a world file "
                "X,Y[,YAW] in its metres (default: the file's own start)");
  c->add_option("--heading", o.heading, "initial heading N, E, S or W (default N)");
  c->add_option("--firmware", o.firmware,
                "firmware ELF, or a raw flash image FILE.bin (e.g. LEGO's); default build/firmware/nxtmap.elf, see "
                "make firmware");
  c->add_option("--listen", o.listen, "PC side of the Bluetooth link: tcp:127.0.0.1:PORT or pty");
  c->add_option("--lcd", o.lcd, "write the LCD picture as PNG at the end");
  c->add_option("--lcd-every", o.lcdEvery,
                "with --lcd FILE.png: also FILE-0001.png, FILE-0002.png, ... every SECONDS of emulated time");
  c->add_option("--speed", o.speed, "max (as fast as possible) or realtime (default max)");
  addWorldRunOptions(*c, o.run, "default: the firmware's own (nxtmap-sim.elf published, nxtmap.elf brick)");
  c->add_option("--seed", o.seed, "random seed of the noise (default 1)");
  c->add_option("--seconds", o.seconds, "emulated time limit in seconds (default 3600)");
  c->add_option("--until", o.until,
                "end the run when: explored, disconnect (the PC left), or time (only the time limit: PCs and "
                "tools may come and go); default disconnect with --listen, else explored (the time limit always "
                "applies)");
  c->add_option("--enter-at", o.enterAt, "emulated second at which Enter is pressed, < 0 never (default 1)");
  c->add_flag("--score", o.score,
              "a PC listens on the radio and keeps the map the brick streams (as the console would); at the end that "
              "map is scored against the world: detected, wrong cells, unsafe free (not with --listen)");
  c->add_option("--png", o.png,
                "with --score: write a PNG of the map that came over the radio, laid on the world as the score lays "
                "it (missed obstacles light red, obstacles mapped free orange, walls mapped on open floor blue, the "
                "robot where it believes it stands)");
  c->add_option("--flash-keep", o.flashKeep,
                "keep the brick's flash in FILE from run to run, as a brick keeps it while switched off (what it "
                "learnt of its wheels); read at the start if it exists, written at the end");
  c->add_flag("--profile", o.profile,
              "print where the instructions of the costliest sensor update went, by firmware function (the "
              "run is slower)");
  return c;
}

int runEmulate(const EmulateOptions& o) {
  if (printNoiseListIfAsked(o.run)) return kExitOk;
  requirePositional(o.world, "emulate: world");
  emu::EmulatedRunOptions run;
  const sim::RobotDescription robot = parseRobot(o.run.robot.empty() ? robotForFirmware(o.firmware) : o.run.robot);
  run.brick.robot = robot;
  run.brick.startJitterDeg = checkStartJitter(o.run.startJitterDeg);
  parseHeading(o.heading);
  run.brick.noise = parseNoise(o.run.noise);
  run.brick.seed = parseSeed(o.seed);
  if (o.speed != "max" && o.speed != "realtime")
    throw CliError("--speed must be max or realtime, not '" + o.speed + "'");
  run.brick.machine.realtime = o.speed == "realtime";
  if (!(o.seconds > 0.0 && o.seconds <= 86400.0))
    throw CliError("--seconds must lie in (0, 86400], not " + std::to_string(o.seconds));
  run.maxSeconds = o.seconds;
  run.pressEnterAtS = o.enterAt;
  const std::string until = o.until.empty() ? (o.listen.empty() ? "explored" : "disconnect") : o.until;
  if (until != "explored" && until != "disconnect" && until != "time")
    throw CliError("--until must be explored, disconnect or time, not '" + o.until + "'");
  if (until == "disconnect" && o.listen.empty()) throw CliError("--until disconnect needs --listen");
  if (o.score && !o.listen.empty()) throw CliError("--score listens on the radio itself: not with --listen");
  if (!o.png.empty() && !o.score) throw CliError("--png draws the scored map: it needs --score");
  std::string pngError;  // checked before the run, as --lcd is: nothing written yet
  if (!o.png.empty() && !fileio::resolveOutputTarget(o.png, pngError)) throw CliError("--png: " + pngError);
  run.stopWhenExplored = until == "explored";
  run.stopWhenPcLeaves = until == "disconnect";
  run.profileWorstUpdate = o.profile;
  std::string lcdError;  // --lcd is checked before the run (a missing folder, a device): nothing written yet
  if (!o.lcd.empty() && !fileio::resolveOutputTarget(o.lcd, lcdError)) throw CliError("--lcd: " + lcdError);
  if (o.lcdEvery != 0.0 && o.lcd.empty()) throw CliError("--lcd-every needs --lcd FILE.png");
  if (o.lcdEvery != 0.0 && !(o.lcdEvery >= 0.001 && o.lcdEvery <= o.seconds))
    throw CliError("--lcd-every must lie in [0.001, --seconds], not " + std::to_string(o.lcdEvery));
  const sim::Site site = loadSiteFile(o.world, robot.cellCm);
  run.brick.startPose = parseSiteStart(site, o.start, o.heading);
  checkStartFits(site, robot, *run.brick.startPose);
  emu::ElfLoad load = emu::ElfImage::load(o.firmware);
  if (!load.image) {
    std::string hint = std::filesystem::exists(o.firmware) ? "" : " (build it with 'make firmware' or pass --firmware)";
    throw CliError("firmware " + load.error + hint);
  }
  std::unique_ptr<emu::LinkEndpoint> link;
  if (!o.listen.empty()) {
    std::string description;
    try {
      link = emu::openLink(o.listen, description);
    } catch (const std::invalid_argument& e) {
      throw CliError(e.what());
    } catch (const std::runtime_error& e) {
      throw CliError(std::string("--listen: ") + e.what());
    }
    std::cout << "link: " << description << " (connect the console there)\n" << std::flush;
    run.brick.link = link.get();
  }

  const std::string keptLine = o.flashKeep.empty() ? "" : keepFlashFrom(o.flashKeep, *load.image);
  // A firmware without our symbols (a raw .bin, another firmware's ELF) runs; what needs them is not measured.
  const bool ours = load.image->symbol("g_explorerDone").has_value();
  if (!ours)
    std::cout << "note             " << o.firmware
              << " has no nxtmap symbols: it runs to the time limit, without the measurements that need them "
                 "(exploration done, sensor updates, static RAM)\n"
              << std::flush;
  std::unique_ptr<LcdSeries> series;
  std::unique_ptr<emu::EmulatedRun> holder;
  std::string seriesError;
  if (o.lcdEvery > 0.0)
    series = std::make_unique<LcdSeries>(o.lcd, static_cast<uint64_t>(o.lcdEvery * static_cast<double>(emu::kMckHz)));
  std::unique_ptr<RadioMirror> mirror;
  if (o.score) {
    mirror = std::make_unique<RadioMirror>();
    run.brick.link = mirror->endpoint();
    run.stopWhenExplored = false;  // the run ends once the map's last changes have come over the radio
  }
  const bool untilExplored = until == "explored";
  if (series || mirror) {
    run.onEvent = [&](uint64_t cycles) {
      if (series && !series->poll(cycles, holder->brick().lcd(), seriesError)) return true;
      return mirror && mirror->follow(*holder, cycles, untilExplored);
    };
  }
  std::cout << keptLine << std::flush;
  holder = std::make_unique<emu::EmulatedRun>(*load.image, site, run);
  emu::EmulatedRun& emulated = *holder;
  const emu::EmulatedRunReport r = emulated.run();
  const std::vector<uint8_t> flash = emulated.brick().machine().flashContents();
  std::string flashError;  // the flash is kept whatever the run's end (a brick that faulted keeps it too)
  if (!o.flashKeep.empty() && !emu::writeFlashState(o.flashKeep, flash, flashError))
    throw CliError("--flash-keep: " + flashError);
  if (!seriesError.empty()) throw CliError(seriesError);

  auto num = [](double v, int d = 1) { return report::formatNumber(v, d); };
  std::ostringstream out;
  out << "run              " << site.name << ", robot " << robot.name << " (" << robot.cellCm << " cm cells), start "
      << (o.start.empty() ? "the world's own" : o.start) << " heading " << o.heading << ", firmware " << o.firmware
      << ", noise " << run.brick.noise.name << ", seed " << run.brick.seed << "\n"
      << "end              "
      << (r.fault      ? "FAULT"
          : r.pcLeft   ? (r.finished ? "the PC disconnected (exploration done)" : "the PC disconnected")
          : r.finished ? "exploration done" + endReason(emulated)
                       : "time limit reached")
      << "\n"
      << "emulated time    " << num(r.emulatedSeconds, 2) << " s\n"
      << "wall time        " << num(r.wallSeconds, 2) << " s (" << num(r.speedRatio()) << "x real time; CPU "
      << num(r.cpuSeconds, 2) << " s = " << num(r.cpuSpeedRatio()) << "x)\n"
      << "instructions     " << r.executed << " executed, " << r.irqs << " interrupts, " << r.idles << " idles, "
      << r.slices << " CPU slices\n"
      << "RAM high-water   "
      << (r.ram.measured ? std::to_string(r.ram.total()) + " B (static " + std::to_string(r.ram.staticBytes) +
                               " + stack " + std::to_string(r.ram.stackBytes) + ") of 65536"
                         : std::string("not measured (the firmware has no end-of-.bss symbol)"))
      << "\n"
      << "sensor updates   " << r.sensorUpdates << ", at most " << r.maxPerUpdate << " instructions each\n"
      << "longest busy     " << r.maxBusy << " instructions between idles\n"
      << "AVR frames       " << r.avrGood << " good, " << r.avrBad << " bad; sonar pings " << r.pings << "\n"
      << "bluetooth        port " << (r.btPortOpen ? "open" : "closed") << ", PC "
      << (r.btConnected ? "connected" : "not connected") << (r.btStreaming ? ", stream mode" : "") << ", " << r.btToPc
      << " bytes to the PC, " << r.btFromPc << " from it\n"
      << "robot            x " << num(r.xCm) << " cm, y " << num(r.yCm) << " cm, heading " << num(r.headingDeg)
      << " deg, driven " << num(r.drivenCm) << " cm\n";
  if (o.profile) {
    out << "costliest update " << r.maxPerUpdate << " instructions, by function:\n";
    out << (r.worstUpdate.empty() ? std::string("  (no function symbols: nothing to attribute)\n")
                                  : emu::profileLines(r.worstUpdate, r.maxPerUpdate, 15));
  }
  if (ours) out << wheelLines(flash, mirror.get());
  std::optional<EmulatedMap> map;
  if (mirror) map = layEmulatedMap(emulated.brick(), *mirror, run.brick.noise.sonar);
  if (map) out << scoreLines(scoreEmulatedMap(*map));
  std::cout << out.str() << std::flush;
  if (map && !o.png.empty()) {
    std::string error;
    if (!writeEmulatedMapPng(o.png, *map, error)) throw CliError(error);
    std::cout << "wrote " << o.png << "\n";
  }
  if (!o.lcd.empty()) {
    std::string error;
    if (!emulated.brick().lcd().savePng(o.lcd, 4, error)) throw CliError(error);
    std::cout << "wrote " << o.lcd << "\n";
    if (series) std::cout << "wrote " << series->written() << " pictures " << LcdSeries::numbered(o.lcd, 1) << " ...\n";
  }
  if (r.fault) {
    printError("the emulated brick stopped: " + r.fault.describe());
    return 1;
  }
  return kExitOk;
}

}  // namespace nxtmap::cli
