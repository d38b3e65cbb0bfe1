#pragma once

// Mailboxing: a primitive that overlaps several cells along a ray is tested once per query, not
// once per cell (Arnaldi, Priol and Bouatouch 1987, "A new space subdivision method for ray
// tracing CSG modelled scenes", The Visual Computer 3(2)).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace raystep {

/// The primitives one query has tested. The classic mailbox, a query number stored in each
/// primitive, would be written by every thread that queries the grid at once. Here the numbers
/// live in an array per thread: each query takes the thread's next number, and a primitive was
/// tested in this query when its entry holds that number. Starting a query costs nothing (no
/// clearing) and a lookup is one load, whatever the number of primitives tested.
///
/// The array is sized for the largest grid the thread has queried (4 bytes a primitive) and
/// lives as long as the thread. Numbers are never reused by a thread before they wrap around, so
/// two grids queried in turn on one thread cannot see each other's entries. Only one Mailbox per
/// thread may be in use at a time; a second would start a new query and make the first test
/// some primitives again (slower, never wrong: the same test gives the same hit).
class Mailbox {
  public:
    /// Starts a query over primitives 0 to `primitive_count` - 1.
    explicit Mailbox(std::size_t primitive_count) : stamps_(thread_stamps()) {
        if (stamps_.last_query.size() < primitive_count) {
            stamps_.last_query.resize(primitive_count, 0);
        }
        if (++stamps_.query == 0) {  // wrapped around after 2^32 queries: forget them all
            std::fill(stamps_.last_query.begin(), stamps_.last_query.end(), 0);
            stamps_.query = 1;
        }
    }

    /// True the first time it is asked about `id` in this query.
    bool first_visit(std::uint32_t id) {
        if (stamps_.last_query[id] == stamps_.query) return false;
        stamps_.last_query[id] = stamps_.query;
        return true;
    }

  private:
    struct Stamps {
        std::vector<std::uint32_t> last_query;  ///< per primitive; 0 is no query
        std::uint32_t query = 0;
    };

    static Stamps& thread_stamps() {
        thread_local Stamps stamps;
        return stamps;
    }

    Stamps& stamps_;
};

}  // namespace raystep
