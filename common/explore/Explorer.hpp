#pragma once
#include <cstdint>
#include <climits>

#include "common/explore/Action.hpp"
#include "common/explore/Counters.hpp"
#include "common/explore/Event.hpp"
#include "common/explore/ExplorerConfig.hpp"
#include "common/explore/Pose.hpp"
#include "common/explore/Route.hpp"
#include "common/explore/TravelPlanner.hpp"
#include "common/grid/MapLayers.hpp"

namespace nxtmap {

// Why a run ended.
// ActionLimit: a safety stop (ExplorerConfig::maxActions actions, or Explorer::kMaxThinks think slices in a row).
enum class ExplorerEnd : uint8_t { Running, Complete, GridFull, ActionLimit };

// The explorer interface: a state machine that consumes events and returns the next action.
// It never calls a driver and never waits. This base owns what every strategy shares: the pose,
// the counters, applying the marking rules to readings, reading every sensor that can still
// teach something at each new cell, and following a route. A strategy only decides where to go
// when the robot stands still with nothing left to read (decide()).
class Explorer {
 public:
  // The safety stop for thinking: think slices answered in a row, with no other action between. A search
  // of the whole 64 x 64 grid is 1,024 slices of ExplorerConfig::searchSliceStates = 8 states; a decision
  // takes a few. More than kMaxThinks in a row is a decision that never ends: the run ends ActionLimit.
  static constexpr uint16_t kMaxThinks = 30000;

  // The map and the planner are owned by the caller and must outlive the explorer.
  Explorer(MapLayers& map, TravelPlanner& planner, const ExplorerConfig& config);
  Explorer(const Explorer&) = delete;
  Explorer& operator=(const Explorer&) = delete;

  // Feeds one event (Event::start() first) and returns what to do next.
  Action step(const Event& e);

  bool finished() const { return end_ != ExplorerEnd::Running; }
  ExplorerEnd end() const { return end_; }
  const Pose& pose() const { return pose_; }
  const Counters& counters() const { return counters_; }
  const MapLayers& map() const { return map_; }
  const ExplorerConfig& config() const { return config_; }
  virtual const char* name() const = 0;

  // Whether reading along `d` from `c` could still teach something: not read from there yet,
  // and an unknown cell within reach before any occupied one.
  bool worthReading(Cell c, Dir d) const;
  // Unknown cells a reading along d from c could reveal (0 when not worth reading).
  int16_t unknownAhead(Cell c, Dir d) const;

 protected:
  ~Explorer() = default;

  // Called when the robot stands still with nothing worth reading and no route to follow.
  // Returns the next action: usually set a route with travelTo()/go() and return follow().
  virtual Action decide() = 0;
  // A move was blocked (only with noise or a real robot): the route is already dropped.
  virtual void onBlocked() {}

  // Route helpers.
  // A travel search from the pose, run in slices of config_.searchSliceStates states (the
  // explorer answers Action::think() in between): searchVisit() sees every reachable cell,
  // cheapest first, and returns true to stop; then searchDone() decides. `purpose` tells the
  // strategy which of its searches it is.
  Action startSearch(uint8_t purpose);
  virtual bool searchVisit(uint8_t purpose, Cell c, uint16_t cost);
  virtual Action searchDone(uint8_t purpose);
  void go(Dir d);                             // one-cell route
  bool travelTo(Cell target, uint16_t cost);  // route from the last planner search
  Action follow();
  bool routeEmpty() const { return route_.empty(); }
  void dropRoute() { route_.clear(); }
  // Whether the robot can set off along d from where it stands: d is on its axis, or it has room to turn
  // (ExplorerConfig::turnNeedsRoom).
  bool canHead(Dir d) const;
  // Number of known-free cells from c along d before the first non-free one.
  int16_t openCells(Cell c, Dir d) const;

  MapLayers& map_;
  TravelPlanner& planner_;
  ExplorerConfig config_;
  Pose pose_;
  Counters counters_;

 private:
  Action next(const Event& e);  // step() but for the safety stop for thinking
  void apply(const Event& e);
  bool nextRead(Sensor& s) const;
  Action finish(ExplorerEnd why);
  Action settle(const Action& a);  // Done from a strategy ends the run as Complete
  Action continueSearch();

  Route route_;
  Dir pendingMove_ = Dir::North;  // direction of the last Move issued
  uint16_t thinks_ = 0;  // think slices answered in a row (kMaxThinks)
  uint32_t actions_ = 0;
  ExplorerEnd end_ = ExplorerEnd::Running;
  bool started_ = false;
  Cell startCell_{};  // where the run started (the blind zone is trusted there)
  // Since the robot came to its cell: whether it has turned a quarter there (its body swept its turning
  // circle, so the blind zone is trusted as at the start), and the directions (bit d: Dir d) whose "no echo"
  // concluded nothing for want of that trust, to be read again after such a turn.
  bool turnedHere_ = false;
  uint8_t blindDirs_ = 0;
  // The last resort before a run ends complete (a body that sweeps its neighbours and a blind zone: see
  // ExplorerConfig::turnNeedsRoom): every direction read from a cell
  // whose neighbour that way is still unknown (a "no echo" that concluded nothing) is forgotten, so the
  // strategy comes back to read it again, and from then on the robot turns a quarter where a "no echo"
  // concluded nothing (proveTurnDue) to read it with the blind zone trusted.
  bool proving_ = false;
  static constexpr int16_t kNoScan = INT16_MIN;
  static constexpr int16_t kProveScanRows = 4;  // rows of the map scanned per think slice
  int16_t scanRow_ = kNoScan;                   // next row to scan for such reads; kNoScan: not scanning
  uint16_t forgotten_ = 0;                      // cells with a direction forgotten by the scan
  Action continueProveScan();
  void forgetBlindReads(Cell c);
  bool proveTurnDue() const;
  bool searching_ = false;
  bool searchEnded_ = false;  // the search is over: searchDone() at the next Thought
  uint8_t searchPurpose_ = 0;
#ifndef NXTMAP_NO_START_SQUARING
  // ExplorerConfig::turnNeedsRoom waived: no goal was within reach with it; until the route is driven or
  // blocked, turns are taken anywhere but where one stalled before. (Not in the RAM-run image: no room.)
  bool roomWaived_ = false;
  void waiveRoom(bool on);
  bool roomWaived() const { return roomWaived_; }
  // Cells where a turn stalled (Event::turnBlocked): no turn is planned there again. When full, a stalled
  // turn makes the cell it turned towards suspect instead (one observation of an obstacle).
  struct StalledTurns final : CellSet {
    static constexpr int kCapacity = 8;
    Cell cells[kCapacity] = {};
    uint8_t count = 0;
    bool contains(Cell c) const override;
    bool full() const { return count == kCapacity; }
  };
  StalledTurns stalledTurns_;
  bool retriedStalls_ = false;  // the stalled turns were forgotten once, before giving up (settle)
#else
  bool roomWaived() const { return false; }
#endif
};

}  // namespace nxtmap
