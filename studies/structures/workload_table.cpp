#include "studies/structures/workload_table.h"

#include <cstdint>

#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"
#include "studies/structures/cross_check.h"

namespace raystep {

namespace {

const StructureMeasurement* find_baseline(const std::vector<StructureMeasurement>& measurements) {
    for (const StructureMeasurement& m : measurements) {
        if (m.baseline) return &m;
    }
    return nullptr;
}

// The baseline's label in a column header: its name up to the first space ("Embree 3.13.5").
std::string short_name(const std::string& name) {
    return name.substr(0, name.find(' '));
}

// ours / theirs, or "-" when either is missing.
std::string ratio(double ours, double theirs) {
    if (!(ours > 0.0) || !(theirs > 0.0)) return "-";
    return three_digits(ours / theirs);
}

std::string per_ray(std::uint64_t count, std::size_t rays, bool counted) {
    if (!counted || rays == 0) return "-";
    return fixed(static_cast<double>(count) / static_cast<double>(rays), 1);
}

}  // namespace

std::string workload_table(const std::vector<StructureMeasurement>& measurements,
                           std::size_t ray_set, int threads) {
    const StructureMeasurement* baseline = find_baseline(measurements);
    const bool measured_baseline = baseline && baseline->failure.empty();
    const std::string versus = baseline ? "x " + short_name(baseline->name) : "";
    const std::string all_threads =
        "Mrays/s, " + std::to_string(threads) + (threads == 1 ? " thread" : " threads");

    std::vector<std::string> headers{"structure", "build ms"};
    if (baseline) headers.push_back(versus);
    headers.push_back("Mrays/s, 1 thread");
    if (baseline) headers.push_back(versus);
    headers.push_back(all_threads);
    if (baseline) headers.push_back(versus);
    headers.push_back("nodes/ray");
    headers.push_back("tests/ray");
    MarkdownTable table(headers);

    // The baseline's numbers that each ratio divides by; 0 (shown as "-") when it has none
    double their_build = 0.0;
    double their_one = 0.0;
    double their_all = 0.0;
    if (measured_baseline) {
        const RayMeasurement& theirs = baseline->ray_sets[ray_set];
        their_build = baseline->build_seconds;
        their_one = mrays_per_second(theirs.rays, theirs.seconds_one_thread);
        their_all = mrays_per_second(theirs.rays, theirs.seconds_all_threads);
    }

    for (const StructureMeasurement& m : measurements) {
        if (!m.failure.empty()) {
            table.add_row({m.name, m.failure});
            continue;
        }
        const RayMeasurement& r = m.ray_sets[ray_set];
        const double one = mrays_per_second(r.rays, r.seconds_one_thread);
        const double all = mrays_per_second(r.rays, r.seconds_all_threads);
        std::vector<std::string> row{m.name, m.builds ? three_digits(m.build_seconds * 1e3) : "-"};
        if (baseline) row.push_back(m.builds ? ratio(m.build_seconds, their_build) : "-");
        row.push_back(one > 0.0 ? three_digits(one) : "-");
        if (baseline) row.push_back(ratio(one, their_one));
        row.push_back(all > 0.0 ? three_digits(all) : "-");
        if (baseline) row.push_back(ratio(all, their_all));
        row.push_back(per_ray(r.stats.nodes, r.rays, r.coverage.nodes));
        row.push_back(per_ray(r.stats.primitive_tests, r.rays, r.coverage.primitive_tests));
        table.add_row(row);
    }
    return table.text();
}

std::vector<std::string> workload_notes(const std::vector<StructureMeasurement>& measurements,
                                        std::size_t ray_set, std::size_t ray_count) {
    std::vector<std::string> notes;
    for (const StructureMeasurement& m : measurements) {
        if (!m.failure.empty()) continue;
        const RayMeasurement& r = m.ray_sets[ray_set];
        if (r.stride > 1) {
            notes.push_back(m.name + ": on " + grouped(r.rays) + " of the " + grouped(ray_count) +
                            " rays (every " + grouped(r.stride) +
                            "th), to keep within its budget of primitive tests");
        }
        if (m.single_thread_build_seconds) {
            // Beside the first row's build (BVH SAH), like for like: our builders use one thread
            std::string note = m.name + " built on one thread: " +
                               three_digits(*m.single_thread_build_seconds * 1e3) + " ms";
            const StructureMeasurement& first = measurements.front();
            if (first.failure.empty() && !first.baseline) {
                note += "; " + first.name + "'s build takes " +
                        ratio(first.build_seconds, *m.single_thread_build_seconds) + " times that";
            }
            notes.push_back(note);
        }
    }
    for (std::string& line : cross_check_lines(measurements, ray_set))
        notes.push_back(line);
    return notes;
}

}  // namespace raystep
