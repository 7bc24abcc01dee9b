// HouseLimits: the bounds every house keeps. HouseNetwork::validate checks them (so a house that
// saves also loads), and loadHouse checks each number from house.yaml and the room maps against
// them before any arithmetic on it. They keep every room-frame and house-frame cell well inside a
// Cell (int16_t) and the merged map small enough to build and export.
#pragma once

#include <cstddef>

namespace nxtmap::network {

// Every room-frame cell (a room map's box, a label, a gateway cell) and every room's to_house
// translation lies within -kMaxCoordCells..kMaxCoordCells; a house-frame cell (a turned room
// cell plus a translation) then lies within twice that, inside int16_t's -32768..32767.
constexpr int kMaxCoordCells = 8192;

// The rooms' boxes in the house frame span at most kMaxHouseSide cells a side: the merged map is
// at most 2048 x 2048 = 4,194,304 cells (205 m a side at 0.1 m cells). HouseNetwork::merged() takes
// 9 bytes a cell for it (two int vote counts and the map's byte): at most 36 MiB.
constexpr int kMaxHouseSide = 2048;

// The room maps together hold at most this many cells (one byte a cell in memory: 16 MiB).
constexpr long kMaxRoomCells = 16L * 1024 * 1024;

constexpr int kMaxRooms = 256;

// A gateway cell lies in its room's map box or at most this many cells outside it: a doorway seen from
// one room only lies beyond the other room's map by the wall's thickness and up to 2 cells more
// (HouseMapper::leadsToMappedRoom); 8 leaves room for walls of 6 cells, and refuses a cell far away.
constexpr int kGatewayReachCells = 8;

// house.yaml is read whole, and only when it is a regular file of at most this many bytes.
constexpr size_t kMaxHouseFileBytes = 1024 * 1024;

}  // namespace nxtmap::network
