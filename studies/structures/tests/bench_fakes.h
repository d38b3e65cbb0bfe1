#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "studies/structures/bench_structure.h"

namespace raystep::testing {

/// A structure for the bench's tests: answers[k] = answer(ray's index), where the index is the
/// ray's origin.x (the tests' rays are numbered so); counts one node and two tests per ray.
class FakeStructure final : public BenchStructure {
  public:
    explicit FakeStructure(std::function<BenchHit(std::size_t)> answer)
        : answer_(std::move(answer)) {}
    void build() override {}
    void closest_hits(const Ray* rays, std::size_t count, BenchHit* answers,
                      TraversalStats* stats) const override {
        for (std::size_t k = 0; k < count; ++k) {
            answers[k] = answer_(static_cast<std::size_t>(rays[k].origin.x));
        }
        if (stats) {
            stats->nodes += count;
            stats->primitive_tests += 2 * count;
        }
    }
    StatsCoverage coverage() const override { return {true, true}; }

  private:
    std::function<BenchHit(std::size_t)> answer_;
};

/// A candidate named `name` whose structure answers by `answer`.
inline BenchCandidate fake_candidate(const std::string& name,
                                     std::function<BenchHit(std::size_t)> answer) {
    BenchCandidate candidate;
    candidate.name = name;
    candidate.make = [answer](const PrimitiveList&) {
        return std::make_unique<FakeStructure>(answer);
    };
    return candidate;
}

/// Ray k has its origin at (k, 0, 0), which is how FakeStructure knows it.
inline std::vector<Ray> numbered_rays(std::size_t count) {
    std::vector<Ray> rays;
    for (std::size_t k = 0; k < count; ++k) {
        rays.push_back(Ray{Vec3(static_cast<double>(k), 0.0, 0.0), Vec3(0.0, 0.0, 1.0)});
    }
    return rays;
}

}  // namespace raystep::testing
