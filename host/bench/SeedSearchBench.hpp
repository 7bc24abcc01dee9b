// The published search (host/plan/SeedSearch) on the 18 Appendix A rooms: nodes visited against solution depth,
// next to the table the method's Appendix A publishes, and how far its paths are from the optimum; part of the
// path-search section of `make bench`.
#pragma once

#include "host/bench/TargetRows.hpp"

namespace nxtmap::bench {

// Prints the table by depth band and adds the section's rows (the published maximum of nodes visited; the
// paths' length against the optimum, for information).
void addSeedSearchRows(TargetRows& rows);

}  // namespace nxtmap::bench
