#include "host/bench/RealismRuns.hpp"

#include <algorithm>

#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/mapping/MappingRun.hpp"

namespace nxtmap::bench {
namespace {

// The start as the variant sets it down: the published cell start when nothing moves it, else a pose.
struct PlacedStart {
  int startCol = 0, startRow = 0;
  std::optional<sim::StartPose> pose;
};

PlacedStart place(const RealismStart& st, const RealismVariant& v, int cellCm, uint64_t seed) {
  PlacedStart p{st.startCol, st.startRow, st.pose};
  if (!p.pose && v.misalignDeg == 0.0 && v.offsetCells == 0.0) return p;
  sim::StartPose pose = p.pose ? *p.pose : st.site->rasterStart(st.startCol, st.startRow, 0.0);
  pose.headingDeg += seed % 2 == 1 ? v.misalignDeg : -v.misalignDeg;
  const double off = v.offsetCells * cellCm;
  pose.cm += sim::Vec2(off, off);
  p.pose = pose;
  return p;
}

mapping::MapScore runRoom(const RealismSet& set, const RealismStart& st, const RealismVariant& v,
                          mapping::Strategy strategy, uint64_t seed) {
  mapping::RunConfig c;
  c.robot = v.robot ? *v.robot : set.robot;
  const PlacedStart p = place(st, v, c.robot->cellCm, seed);
  c.startCol = p.startCol;
  c.startRow = p.startRow;
  c.heading = sim::Heading::N;
  c.startPose = p.pose;
  c.noise = v.noise;
  c.seed = seed;
  c.strategy = strategy;
  c.sensorsTogether = v.sensorsTogether;
  mapping::MappingRun run(*st.site, c);
  run.runToEnd();
  return mapping::scoreRun(run);
}

// The merged house map scored like a room's map. HouseMapper keeps its belief to itself, so the believed cell
// is taken as the true one (Tally::lostKnown is false for houses).
mapping::MapScore scoreHouseMap(const house::HouseMapper& m) {
  mapping::ScoreInput in;
  in.scene = &m.robot().scene();
  in.truth = &m.world();
  in.frame = m.robot().frame();
  in.startCol = m.config().startCol;
  in.startRow = m.config().startRow;
  in.freeCells = m.explorerConfig().geometry.freeCells();
  in.hitCells = m.explorerConfig().geometry.hitCells();
  const network::RoomMap merged = m.network().merged();
  for (int y = merged.minY(); y <= merged.maxY(); ++y) {
    for (int x = merged.minX(); x <= merged.maxX(); ++x) {
      const Cell cell{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      const CellState state = merged.at(cell);
      if (state == CellState::Unknown) continue;
      mapping::KnownCell k;
      k.state = state;
      m.houseFrame().toWorld(cell, k.col, k.row);
      in.known.push_back(k);
    }
  }
  in.trueCentreCm = sim::Vec2(m.robot().xCm(), m.robot().yCm());
  in.frame.cellOf(in.trueCentreCm, in.believedCol, in.believedRow);
  return mapping::scoreMap(in);
}

// One house: its honest scores, and its agreement % (house::scoreHouse) in `agreementPct`.
mapping::MapScore runHouse(const RealismSet& set, const RealismStart& st, const RealismVariant& v,
                           mapping::Strategy strategy, uint64_t seed, double& agreementPct) {
  house::HouseConfig c;
  c.robot = v.robot ? *v.robot : set.robot;
  const PlacedStart p = place(st, v, c.robot->cellCm, seed);
  c.startCol = p.startCol;
  c.startRow = p.startRow;
  c.startPose = p.pose;
  c.noise = v.noise;
  c.seed = seed;
  c.strategy = strategy;
  // Houses at the published robot's 10 cm cells need a grid larger than the brick's (see HouseBench).
  if (c.robot->cellCm < 20) c.grid = *mapping::GridCapacity::ofCells(128);
  house::HouseMapper m(*st.site, c);
  m.run();
  agreementPct = house::scoreHouse(m).agreementPct();
  return scoreHouseMap(m);
}

}  // namespace

void Tally::add(const mapping::MapScore& s) {
  ++runs;
  lost += s.lost ? 1 : 0;
  detected += s.detectedPct();
  worstDetected = std::min(worstDetected, s.detectedPct());
  wrong += s.wrongCells;
  unsafeFree += s.unsafeFree;
  detectedAligned += s.detectedPctAligned();
  wrongAligned += s.wrongCellsAligned;
}

Tally runRealism(const RealismSet& set, const RealismVariant& variant, mapping::Strategy strategy,
                 const RealismProgress& progress) {
  Tally t;
  t.lostKnown = !set.houses;
  for (const RealismStart& st : set.starts) {
    for (int k = 1; k <= set.seeds; ++k) {
      const auto seed = static_cast<uint64_t>(k);
      double agreementPct = 0.0;
      t.add(set.houses ? runHouse(set, st, variant, strategy, seed, agreementPct)
                       : runRoom(set, st, variant, strategy, seed));
      t.agreement += agreementPct;
      if (progress) progress();
    }
  }
  return t;
}

RealismVariant presetVariant(const std::string& preset) {
  RealismVariant v;
  v.noise = *sim::noiseProfileByName(preset);
  return v;
}

}  // namespace nxtmap::bench
