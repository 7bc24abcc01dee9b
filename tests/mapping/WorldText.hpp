// Helper of the mapping tests: a site from the text of an nxtmap world file (its scene and its start).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "host/sim/Site.hpp"
#include "host/sim/WorldFile.hpp"

namespace nxtmap::mapping::test {

inline sim::Site siteFromWorldText(const std::string& text) {
  const sim::WorldFileLoad load = sim::parseWorldFile(text, "room.yaml");
  EXPECT_TRUE(load.world) << load.error;
  sim::Site site;
  site.name = "room";
  site.scene = load.world->scene;
  site.start = sim::StartPose{load.world->startCm, load.world->startHeadingDeg};
  return site;
}

}  // namespace nxtmap::mapping::test
