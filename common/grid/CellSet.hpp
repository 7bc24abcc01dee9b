#pragma once

#include "common/grid/Cell.hpp"

namespace nxtmap {

// A set of cells asked one cell at a time (e.g. the doorways a room run holds shut), so a user such
// as the pilot need not know how the set is stored.
class CellSet {
 public:
  virtual bool contains(Cell c) const = 0;

 protected:
  ~CellSet() = default;
};

}  // namespace nxtmap
