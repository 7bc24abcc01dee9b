// The mode machine's house commands (a confined Explore, GoTo, EnterRoom, Scan from the PC): carried out by the
// HouseBrick from where the robot stands, its actions run by the same runner as the robot's own runs.
#include "firmware/app/MapExport.hpp"
#include "firmware/app/ModeMachine.hpp"

namespace nxtmap::fw {

#if defined(NXTMAP_SIM_GEOMETRY)
extern "C" MapExport g_mapExport;  // ModeMachine.cpp
#endif

void ModeMachine::houseCommand(const protocol::Command& c, uint32_t nowMs) {
  if constexpr (kHouseCommands) {
    if (house_ == nullptr) return;  // refused like an unknown command
    const Pose here = pose();
    runner_.abort();
    follower_.abort();
    safety_.clear();
    tacho_.clearFault();
    poseFromPath_ = false;
    if (!house_->active()) house_->useWheels(knownWheels());  // a house starts: from what the brick knows
    DriveAction first;
    if (c.kind == protocol::CommandKind::Explore)
      first = house_->explore(c.explore, here, roomId_);  // a new room: the map is cleared
    else if (c.kind == protocol::CommandKind::GoTo)
      first = house_->goTo(c.goTo, here);
    else if (c.kind == protocol::CommandKind::Scan)
      first = house_->scan(c.scan, here);
    else
      first = house_->enterRoom(c.enterRoom, here);
    afterHouseStep(first, nowMs);
  }
}

void ModeMachine::afterHouseStep(const DriveAction& next, uint32_t nowMs) {
  if constexpr (kHouseCommands) {
    if (house_->takeMapRestart()) link_.mapRestarted();
    roomId_ = house_->roomId();
    mapChanged();
    pending_ = next;
    if (house_->running()) {
      runner_.begin(next, wheels(), nowMs);
      return;
    }
    ++finishes_;
    keep(house_->wheels());  // what the house's runs learnt: what the brick knows, and into the store
#if defined(NXTMAP_SIM_GEOMETRY)
    g_mapExport.fill(grid());
#endif
  }
}

void ModeMachine::leaveHouse() {
  if constexpr (kHouseCommands) {
    if (!houseActive()) return;
    runner_.abort();
    house_->abort();
    house_->deactivate();
    mode_ = Mode::Idle;
    restAt(house_->pose());
  }
}

}  // namespace nxtmap::fw
