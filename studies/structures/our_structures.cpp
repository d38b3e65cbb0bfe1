#include "studies/structures/our_structures.h"

#include <optional>

#include "stages/4_accel/uniform_grid.h"

namespace raystep {

namespace {

// Adapts a structure with the stage-4 query `closest_hit(ray, stats)`; Accelerator is Bvh or
// UniformGrid, built by `build` into the optional.
template <class Accelerator>
class AcceleratorStructure : public BenchStructure {
  public:
    explicit AcceleratorStructure(const PrimitiveList& primitives) : primitives_(primitives) {}

    void closest_hits(const Ray* rays, std::size_t count, BenchHit* answers,
                      TraversalStats* stats) const override {
        const std::size_t spheres = primitives_.spheres.size();
        const std::size_t triangles = primitives_.triangles.size();
        for (std::size_t k = 0; k < count; ++k) {
            answers[k] = bench_hit(accelerator_->closest_hit(rays[k], stats), spheres, triangles);
        }
    }

    StatsCoverage coverage() const override { return {true, true}; }

  protected:
    const PrimitiveList& primitives_;
    std::optional<Accelerator> accelerator_;
};

class BvhStructure final : public AcceleratorStructure<Bvh> {
  public:
    BvhStructure(const PrimitiveList& primitives, BvhSplit split)
        : AcceleratorStructure(primitives), split_(split) {}
    void build() override { accelerator_.emplace(primitives_, split_); }

  private:
    BvhSplit split_;
};

class GridStructure final : public AcceleratorStructure<UniformGrid> {
  public:
    using AcceleratorStructure::AcceleratorStructure;
    void build() override { accelerator_.emplace(primitives_); }
};

// Brute force has nothing to build; each query tests every primitive, so that is its count.
class BruteForce final : public BenchStructure {
  public:
    explicit BruteForce(const PrimitiveList& primitives) : primitives_(primitives) {}

    void build() override {}

    void closest_hits(const Ray* rays, std::size_t count, BenchHit* answers,
                      TraversalStats* stats) const override {
        const std::size_t spheres = primitives_.spheres.size();
        const std::size_t triangles = primitives_.triangles.size();
        for (std::size_t k = 0; k < count; ++k) {
            answers[k] = bench_hit(closest_hit(rays[k], primitives_), spheres, triangles);
        }
        if (stats) stats->primitive_tests += count * (spheres + triangles);
    }

    StatsCoverage coverage() const override { return {false, true}; }

  private:
    const PrimitiveList& primitives_;
};

}  // namespace

BenchCandidate bvh_candidate(BvhSplit split) {
    BenchCandidate candidate;
    candidate.name = split == BvhSplit::sah ? "BVH SAH" : "BVH median";
    candidate.make = [split](const PrimitiveList& primitives) {
        return std::make_unique<BvhStructure>(primitives, split);
    };
    return candidate;
}

BenchCandidate grid_candidate() {
    BenchCandidate candidate;
    candidate.name = "grid";
    candidate.make = [](const PrimitiveList& primitives) {
        return std::make_unique<GridStructure>(primitives);
    };
    return candidate;
}

BenchCandidate brute_force_candidate() {
    BenchCandidate candidate;
    candidate.name = "brute force";
    candidate.make = [](const PrimitiveList& primitives) {
        return std::make_unique<BruteForce>(primitives);
    };
    candidate.subsampled = true;
    candidate.max_primitives = kBruteForceLimit;
    candidate.builds = false;
    return candidate;
}

std::vector<BenchCandidate> our_structures() {
    return {bvh_candidate(BvhSplit::sah), bvh_candidate(BvhSplit::median), grid_candidate(),
            brute_force_candidate()};
}

}  // namespace raystep
