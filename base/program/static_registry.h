#pragma once

#include <utility>
#include <vector>

namespace raystep {

/// What a layer above adds to a program without the layer below naming it: the studies' `bench`
/// command in `raystep`, Embree's baseline in the bench, the speed-against-error study in
/// raystep-reference. A static `Registration` in the adding .cpp file registers its entry before
/// main runs, so a program has exactly the entries of the files it links. That .cpp file must be
/// linked as an object (a CMake OBJECT library), not from a static archive, whose unreferenced
/// members the linker drops.
template <typename Entry>
class StaticRegistry {
  public:
    /// Every entry registered so far, in the order of registration.
    static const std::vector<Entry>& entries() { return storage(); }

    /// Adds `entry` when constructed.
    struct Registration {
        explicit Registration(Entry entry) { storage().push_back(std::move(entry)); }
    };

  private:
    // A function-local static, so that a registration from another file's static object finds it
    // built whatever order the linker put the files in.
    static std::vector<Entry>& storage() {
        static std::vector<Entry> entries;
        return entries;
    }
};

}  // namespace raystep
