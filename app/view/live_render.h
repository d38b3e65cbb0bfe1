#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "base/scene/scene.h"
#include "renderer/tile_renderer.h"
#include "renderer/view.h"

namespace raystep {

/// A render that grows on its own thread while the page asks what is new: the image behind
/// `raystep view`. Each start() begins a new generation and cancels the one before. Every tile
/// that finishes gets the next number of one running sequence, so the page asks only for the
/// tiles after the last number it saw.
/// The samples per pixel of the passes a live render of `spp` samples shows: 1, 4, 16, ... (every
/// pattern's counts are squares) while below `spp`, then `spp` itself. The passes before the last
/// sum to under 4/3 of the largest of them: a third of the last's time when spp is a power of 4,
/// and up to 4/3 of it just above one (spp 17 renders 1, 4, 16 and 17).
std::vector<int> progressive_passes(int spp);

class LiveRender {
  public:
    enum class State { idle, rendering, done, failed };

    /// A finished tile as display bytes (app/view/display_pixels.h).
    struct Tile {
        TileRect rect;
        std::string pixels;
    };

    /// What changed since a sequence number, and where the render is.
    struct Changes {
        std::uint64_t generation = 0;
        View view = View::full;
        State state = State::idle;
        std::string error;  ///< why it failed: a stub's message, say
        int width = 0;
        int height = 0;
        std::size_t pixels_done = 0;  ///< of the pass under way
        int samples = 1;              ///< the samples per pixel of the pass under way
        int target_samples = 1;       ///< the scene's: the last pass's
        double seconds = 0.0;         ///< since the start, or the whole render once done
        std::uint64_t sequence = 0;   ///< the last tile's number: ask from here next time
        std::vector<Tile> tiles;
    };

    LiveRender() = default;
    LiveRender(const LiveRender&) = delete;
    LiveRender& operator=(const LiveRender&) = delete;
    ~LiveRender() { stop(); }

    /// Cancels the render under way, if any, and starts `view` of `scene` on `threads` threads (0:
    /// one per hardware thread). A view that averages a pixel's samples renders in passes of
    /// progressive_passes(scene's spp), each shown as it comes, so that the image is seen
    /// converging; the last pass is the scene's own render. Returns the new generation.
    std::uint64_t start(Scene scene, View view, int threads);

    /// The tiles finished after `sequence`, all of them when `generation` is not the current
    /// one. Views that scale the whole image once it is done (depth, cost) send every pixel
    /// again, scaled, when the last tile is done.
    Changes changes_since(std::uint64_t generation, std::uint64_t sequence) const;

    /// Cancels the render under way and waits for its threads.
    void stop();

  private:
    void stop_locked();
    void run(Scene scene, View view, int threads, std::uint64_t generation);
    void add_tile(std::uint64_t generation, const Image& image, const TileRect& rect);

    std::mutex control_;        ///< start and stop, one at a time: they join and replace thread_
    mutable std::mutex mutex_;  ///< what the render thread writes and the page reads
    std::thread thread_;
    std::atomic<bool> cancel_{false};
    std::uint64_t generation_ = 0;
    View view_ = View::full;
    State state_ = State::idle;
    std::string error_;
    int width_ = 0;
    int height_ = 0;
    std::size_t pixels_done_ = 0;
    int samples_ = 1;
    int target_samples_ = 1;
    std::chrono::steady_clock::time_point started_;
    double seconds_ = 0.0;
    std::uint64_t sequence_ = 0;
    std::vector<std::pair<std::uint64_t, Tile>> tiles_;  ///< each with the number it got
};

/// The state's name in the page's JSON: idle, rendering, done or failed.
const char* live_render_state_name(LiveRender::State state);

}  // namespace raystep
