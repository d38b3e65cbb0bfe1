#include "studies/structures/growth.h"

#include <algorithm>
#include <set>

#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"
#include "studies/structures/bench_rays.h"
#include "studies/structures/bumpy_torus.h"

namespace raystep {

namespace {

// The same rays at every size relative to the mesh: the tori differ only in tessellation, so
// the growth in cost is the structures', not the workload's.
constexpr std::uint64_t kGrowthSeed = 4099;

}  // namespace

std::vector<int> growth_rings() {
    return {16, 32, 64, 128, 256, 512};
}

std::vector<GrowthRow> measure_growth(const std::vector<BenchCandidate>& candidates,
                                      std::size_t rays, const MeasureOptions& options) {
    MeasureOptions one_thread = options;
    one_thread.all_threads = false;

    std::vector<GrowthRow> rows;
    for (const int rings : growth_rings()) {
        PrimitiveList primitives;
        primitives.triangles = bumpy_torus(rings, 2 * rings);
        const std::vector<RaySet> ray_sets{
            {"growth", grouped(rays) + " incoherent rays",
             incoherent_rays(bench_bounds(primitives), rays, kGrowthSeed)}};

        GrowthRow& row = rows.emplace_back();
        row.triangles = primitives.triangles.size();
        std::vector<BenchCandidate> sized = candidates;
        for (BenchCandidate& candidate : sized) {
            if (candidate.subsampled) {
                candidate.max_primitives =
                    std::min(candidate.max_primitives, kGrowthBruteForceLimit);
            }
            // No column for a one-thread build here: one build per size says enough
            candidate.make_single_threaded = nullptr;
        }
        MeasureOptions told = one_thread;
        if (options.progress) {
            told.progress = [&](const std::string& what) {
                options.progress(grouped(row.triangles) + " triangles, " + what);
            };
        }
        row.measurements = measure_candidates(sized, primitives, ray_sets, told);
    }
    return rows;
}

std::string growth_table(const std::vector<GrowthRow>& rows) {
    if (rows.empty()) return "";
    std::vector<std::string> headers{"triangles"};
    for (const StructureMeasurement& m : rows.front().measurements) {
        headers.push_back(m.name + " build ms");
        headers.push_back(m.name + " Mrays/s");
    }
    MarkdownTable table(headers);

    std::set<std::string> failures;  // "name: reason", once each
    std::vector<std::string> notes;
    for (const GrowthRow& row : rows) {
        std::vector<std::string> cells{grouped(row.triangles)};
        for (const StructureMeasurement& m : row.measurements) {
            if (!m.failure.empty()) {
                cells.push_back("-");
                cells.push_back("-");
                if (m.failure.rfind("skipped", 0) != 0) failures.insert(m.name + ": " + m.failure);
                continue;
            }
            const RayMeasurement& r = m.ray_sets.front();
            cells.push_back(m.builds ? three_digits(m.build_seconds * 1e3) : "-");
            cells.push_back(three_digits(mrays_per_second(r.rays, r.seconds_one_thread)));
            if (r.stride > 1) {
                notes.push_back(m.name + " at " + grouped(row.triangles) + " triangles: on " +
                                grouped(r.rays) + " of the rays (every " + grouped(r.stride) +
                                "th)");
            }
        }
        table.add_row(cells);
    }

    // A blank line first: Markdown would read a line right under a table as one more row
    std::string text = table.text() + (notes.empty() && failures.empty() ? "" : "\n");
    for (const std::string& note : notes)
        text += "- " + note + "\n";
    for (const std::string& failure : failures)
        text += "- " + failure + "\n";
    return text;
}

}  // namespace raystep
