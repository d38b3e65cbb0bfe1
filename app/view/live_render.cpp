#include "app/view/live_render.h"

#include <algorithm>
#include <exception>
#include <utility>

#include "app/view/display_pixels.h"
#include "renderer/render_scene.h"

namespace raystep {

std::uint64_t LiveRender::start(Scene scene, View view, int threads) {
    std::lock_guard<std::mutex> control(control_);
    stop_locked();
    std::uint64_t generation = 0;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        generation = ++generation_;
        view_ = view;
        state_ = State::rendering;
        error_.clear();
        width_ = scene.width;
        height_ = scene.height;
        pixels_done_ = 0;
        target_samples_ = averages_samples(view) ? scene.samples_per_pixel : 1;
        samples_ = progressive_passes(target_samples_).front();
        started_ = std::chrono::steady_clock::now();
        seconds_ = 0.0;
        tiles_.clear();
    }
    cancel_ = false;
    thread_ = std::thread(&LiveRender::run, this, std::move(scene), view, threads, generation);
    return generation;
}

void LiveRender::stop() {
    std::lock_guard<std::mutex> control(control_);
    stop_locked();
}

void LiveRender::stop_locked() {
    cancel_ = true;
    if (thread_.joinable()) thread_.join();
    std::lock_guard<std::mutex> lock(mutex_);
    if (state_ == State::rendering) state_ = State::idle;
}

void LiveRender::add_tile(std::uint64_t generation, const Image& image, const TileRect& rect) {
    Tile tile{rect, {}};
    append_display_pixels(image, rect, tile.pixels);
    std::lock_guard<std::mutex> lock(mutex_);
    if (generation != generation_) return;
    pixels_done_ +=
        static_cast<std::size_t>(rect.x1 - rect.x0) * static_cast<std::size_t>(rect.y1 - rect.y0);
    tiles_.emplace_back(++sequence_, std::move(tile));
}

std::vector<int> progressive_passes(int spp) {
    std::vector<int> passes;
    for (int samples = 1; samples < spp; samples *= 4)
        passes.push_back(samples);
    passes.push_back(std::max(spp, 1));
    return passes;
}

void LiveRender::run(Scene scene, View view, int threads, std::uint64_t generation) {
    try {
        RenderOptions options;
        options.view = view;
        options.threads = threads;
        options.cancel = &cancel_;
        options.on_tile = [this, generation](const Image& image, const TileRect& rect) {
            add_tile(generation, image, rect);
        };
        const std::vector<int> passes =
            progressive_passes(averages_samples(view) ? scene.samples_per_pixel : 1);
        for (std::size_t pass = 0; pass < passes.size(); ++pass) {
            {
                std::lock_guard<std::mutex> lock(mutex_);
                if (generation != generation_) return;
                samples_ = passes[pass];
                pixels_done_ = 0;
            }
            Scene pass_scene = scene;
            if (averages_samples(view)) pass_scene.samples_per_pixel = passes[pass];
            const Image image = render_image(prepare_render_scene(pass_scene), options);
            if (cancel_) return;
            // The finished pass replaces the tiles, so that a page that starts watching now
            // sees it whole: depth and cost are scaled only now.
            Tile whole{{0, 0, image.width(), image.height()}, {}};
            append_display_pixels(image, whole.rect, whole.pixels);
            std::lock_guard<std::mutex> lock(mutex_);
            if (generation != generation_) return;
            tiles_.clear();
            tiles_.emplace_back(++sequence_, std::move(whole));
        }
        std::lock_guard<std::mutex> lock(mutex_);
        state_ = State::done;
        seconds_ =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    } catch (const std::exception& error) {
        std::lock_guard<std::mutex> lock(mutex_);
        state_ = State::failed;
        error_ = error.what();
        seconds_ =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    }
}

LiveRender::Changes LiveRender::changes_since(std::uint64_t generation,
                                              std::uint64_t sequence) const {
    std::lock_guard<std::mutex> lock(mutex_);
    Changes changes;
    changes.generation = generation_;
    changes.view = view_;
    changes.state = state_;
    changes.error = error_;
    changes.width = width_;
    changes.height = height_;
    changes.pixels_done = pixels_done_;
    changes.samples = samples_;
    changes.target_samples = target_samples_;
    changes.seconds =
        state_ == State::rendering
            ? std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count()
            : seconds_;
    changes.sequence = sequence_;
    const std::uint64_t after = generation == generation_ ? sequence : 0;
    for (const auto& [number, tile] : tiles_) {
        if (number > after) changes.tiles.push_back(tile);
    }
    return changes;
}

const char* live_render_state_name(LiveRender::State state) {
    switch (state) {
        case LiveRender::State::idle:
            return "idle";
        case LiveRender::State::rendering:
            return "rendering";
        case LiveRender::State::done:
            return "done";
        case LiveRender::State::failed:
            return "failed";
    }
    return "idle";
}

}  // namespace raystep
