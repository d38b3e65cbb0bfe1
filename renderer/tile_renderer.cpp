#include "renderer/tile_renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "renderer/progress_bar.h"
#include "renderer/render_pixel.h"

namespace raystep {

namespace {

constexpr int kTileSize = 16;

// Shared by the workers: the next tile to take, the pixels done, and the first failure.
class TileQueue {
  public:
    TileQueue(int width, int height, const std::atomic<bool>* cancel)
        : cancel_(cancel),
          width_(width),
          tiles_x_((width + kTileSize - 1) / kTileSize),
          tile_count_(tiles_x_ * ((height + kTileSize - 1) / kTileSize)),
          height_(height) {}

    /// The next tile's first pixel, or false when none is left or the render failed.
    bool take(int& x0, int& y0) {
        if (failed_.load() || (cancel_ && cancel_->load())) return false;
        const int tile = next_.fetch_add(1);
        if (tile >= tile_count_) return false;
        x0 = (tile % tiles_x_) * kTileSize;
        y0 = (tile / tiles_x_) * kTileSize;
        return true;
    }

    void fail(std::exception_ptr error) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_) error_ = error;
        failed_ = true;
    }

    void add_done(std::size_t pixels) { done_ += pixels; }
    std::size_t done() const { return done_.load(); }

    void worker_finished() {
        std::lock_guard<std::mutex> lock(mutex_);
        ++finished_workers_;
        changed_.notify_all();
    }

    /// Waits until `workers` have finished or `period` has passed; true when all have finished.
    bool wait_for_workers(int workers, std::chrono::milliseconds period) {
        std::unique_lock<std::mutex> lock(mutex_);
        return changed_.wait_for(lock, period, [&] { return finished_workers_ == workers; });
    }

    std::exception_ptr error() const { return error_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    const std::atomic<bool>* cancel_;
    int width_;
    int tiles_x_;
    int tile_count_;
    int height_;
    std::atomic<int> next_{0};
    std::atomic<std::size_t> done_{0};
    std::atomic<bool> failed_{false};
    std::mutex mutex_;
    std::condition_variable changed_;
    int finished_workers_ = 0;
    std::exception_ptr error_;
};

using TileDone = std::function<void(const Image& image, const TileRect& tile)>;

void render_tiles(const PixelFunction& pixel, const TileDone& on_tile, TileQueue& queue,
                  Image& image) {
    try {
        int x0 = 0;
        int y0 = 0;
        while (queue.take(x0, y0)) {
            const int x1 = std::min(x0 + kTileSize, queue.width());
            const int y1 = std::min(y0 + kTileSize, queue.height());
            for (int j = y0; j < y1; ++j) {
                for (int i = x0; i < x1; ++i) {
                    image.set(i, j, pixel(i, j));
                }
            }
            queue.add_done(static_cast<std::size_t>((x1 - x0) * (y1 - y0)));
            if (on_tile) on_tile(image, {x0, y0, x1, y1});
        }
    } catch (...) {
        queue.fail(std::current_exception());
    }
    queue.worker_finished();
}

// Every pixel on `threads` threads (0: one per hardware thread), with this thread drawing `bar`,
// which counts `per_pixel` for each pixel done.
Image render_tiles_in_pool(int width, int height, const PixelFunction& pixel, int threads,
                           ProgressBar& bar, std::size_t per_pixel, const TileDone& on_tile = {},
                           const std::atomic<bool>* cancel = nullptr) {
    Image image(width, height);
    TileQueue queue(width, height, cancel);

    const int wanted =
        threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(wanted));
    try {
        for (int w = 0; w < wanted; ++w) {
            pool.emplace_back(render_tiles, std::cref(pixel), std::cref(on_tile), std::ref(queue),
                              std::ref(image));
        }
    } catch (const std::system_error&) {
        // Fewer threads than asked for (a process limit in a sandbox, say): the ones running
        // share the work, and the image is the same.
    }

    if (pool.empty()) {
        render_tiles(pixel, on_tile, queue, image);
    } else {
        // This thread draws the progress bar until every worker is done.
        const int workers = static_cast<int>(pool.size());
        while (!queue.wait_for_workers(workers, std::chrono::milliseconds(100))) {
            bar.update(queue.done() * per_pixel);
        }
        for (std::thread& thread : pool)
            thread.join();
    }

    if (queue.error()) {
        bar.abandon();
        std::rethrow_exception(queue.error());
    }
    bar.finish();
    return image;
}

}  // namespace

Image render_pixels(int width, int height, const PixelFunction& pixel, int threads) {
    ProgressBar no_bar("", 0, false);
    return render_tiles_in_pool(width, height, pixel, threads, no_bar, 1);
}

Image render_image(const RenderScene& render_scene, const RenderOptions& options) {
    const Scene& scene = *render_scene.scene;
    const View view = options.view;
    std::vector<PixelRecord>* records = options.records;
    if (records) {
        records->assign(
            static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height),
            PixelRecord{});
    }
    // Each pixel writes only its own record, so the threads share nothing.
    const PixelFunction pixel = [&render_scene, view, records, &scene](int i, int j) {
        if (!records) return render_pixel(render_scene, view, i, j);
        PixelRecorder recorder(
            (*records)[static_cast<std::size_t>(j) * static_cast<std::size_t>(scene.width) +
                       static_cast<std::size_t>(i)],
            scene.dialect);
        return render_pixel(render_scene, view, i, j, recorder);
    };
    // A sampled render counts its camera samples. A pixel takes all its samples at once (stage
    // 8's pixel_colour needs the whole n x n set to place them in strata), so the count moves a
    // pixel's samples at a time: no pass-by-pass image exists to show, and the bar does not
    // pretend there is one.
    const std::size_t pixels =
        static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
    const bool sampled = averages_samples(view) && scene.samples_per_pixel > 1;
    const std::size_t per_pixel =
        sampled ? static_cast<std::size_t>(scene.samples_per_pixel) : std::size_t{1};
    ProgressBar bar(options.label, pixels * per_pixel, options.progress, stderr,
                    sampled ? "samples" : "");
    Image image = render_tiles_in_pool(scene.width, scene.height, pixel, options.threads, bar,
                                       per_pixel, options.on_tile, options.cancel);
    finish_view(image, view);
    return image;
}

}  // namespace raystep
