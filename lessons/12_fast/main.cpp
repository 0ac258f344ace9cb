// Lesson 12: the fast path. Lesson 07's scene and shading from a tiled,
// multi-threaded SIMD renderer, over frames of a camera orbiting the target;
// it prints the median time per frame and, where Mesa's llvmpipe is
// installed, the same frames' time in llvmpipe on as many threads. Read
// docs/12_fast.md beside it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "07_normal_mapping/mapped_cli.hpp"
#include "orbit.hpp"
#include "peer/peer.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/image_metrics.hpp"
#include "rasterlab/main_guard.hpp"
#include "renderer.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 12, the fast path: lesson 07's image from a tiled, multi-threaded SIMD "
        "renderer, timed over frames of an orbiting camera (and against Mesa's llvmpipe)."};
    rl::ImageOptions image_options{"12_fast.tga"};
    normal_mapping::MappedCli cli;
    fast::FastOptions options;
    int frames = 30;
    bool peer = true;
    normal_mapping::add_mapped_options(app, cli, "floor, globe and crate from obj/");
    rl::add_image_options(app, image_options);
    app.add_option("--frames", frames,
                   "Frames to render, the camera orbiting the target once; the last one is the "
                   "view the camera options give, and is written (1 to 1000: each frame "
                   "sets up every triangle again, whatever the image size)")
        ->capture_default_str()
        ->check(rl::range(1, 1000));
    app.add_option("--threads", options.threads, "Threads (0: one per core, up to 256)")
        ->capture_default_str()
        ->check(rl::range(0, 256));
    app.add_option("--tile-size", options.tile_size,
                   "Tile side in pixels (8 to 1024, a multiple of 8)")
        ->capture_default_str()
        ->check(rl::range(8, 1024));
    rl::Option* no_peer =
        app.add_flag("!--no-peer", peer, "Do not time Mesa's llvmpipe on the same frames");
    std::string peer_output;
    app.add_option("--peer-output", peer_output, "Also write llvmpipe's last frame here")
        ->excludes(no_peer);
    return app.run(argc, argv, "12_fast", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        // Both images are written together at the end, or neither: a peer that
        // fails (or a signal while it is timed) replaces nothing.
        rl::ImageOutputs outputs;
        outputs.check(output);
        if (!peer_output.empty()) {
#ifndef RASTERLAB_LLVMPIPE
            throw std::invalid_argument(
                "--peer-output: this build has no llvmpipe peer (OSMesa, libosmesa6-dev, missing; "
                "or a sanitized build)");
#endif
            outputs.check(peer_output);
        }
        fast::check_frames(frames, width, height);
        normal_mapping::MappedScene scene =
            normal_mapping::load_scene(cli, width, height, "12_fast");
        options.render = cli.options;  // with the lighting and output load_scene set
        fast::Renderer renderer(scene.models, width, height, options);
        if (options.threads > renderer.threads())
            std::fprintf(stderr,
                         "12_fast: warning: --threads %d: this machine runs %d threads at once; "
                         "using %d\n",
                         options.threads, renderer.threads(), renderer.threads());
        const auto [ms, stages, counts] = fast::render_orbit(renderer, scene.camera, frames);
        outputs.stage(output, renderer.frame());
        std::printf(
            "%d frames of %dx%d on %d threads (%s): median %.2f ms per frame (first excluded); "
            "%zu triangles, %.1f M triangles/s, %.1f M pixels shaded/s; into %s\n",
            frames, width, height, renderer.threads(), fast::simd_target(), ms,
            counts.pipeline.drawn, static_cast<double>(counts.pipeline.drawn) / ms / 1e3,
            static_cast<double>(counts.tiles.shaded) / ms / 1e3, output.c_str());
        std::printf(
            "median per frame: vertex %.2f ms, setup %.2f, binning %.2f, tiles %.2f; %.0f%% of "
            "the shader's lanes used in the last\n",
            stages.vertex, stages.setup, stages.binning, stages.tiles,
            100.0 * static_cast<double>(counts.tiles.shaded) /
                static_cast<double>(std::max<std::uint64_t>(counts.tiles.lanes, 1)));
        if (!peer) {
            outputs.commit();
            return 0;
        }
        // The peer's module (and Mesa and LLVM with it) is loaded only now.
        std::unique_ptr<fast::Peer> llvmpipe;
        try {
            llvmpipe = fast::load_llvmpipe_peer(width, height, renderer.threads());
        } catch (const fast::PeerUnavailable& e) {
            if (!peer_output.empty()) throw;
            std::printf("llvmpipe peer skipped: %s\n", e.what());
            outputs.commit();
            return 0;
        }
        llvmpipe->upload(scene.models, options.render);
        std::vector<double> peer_times;
        for (int i = 0; i < frames; ++i)
            peer_times.push_back(llvmpipe->render(fast::orbit(scene.camera, i, frames)));
        const double peer_ms = fast::median_after_first(peer_times);
        const rl::Image peer_frame = llvmpipe->frame();
        const rl::ImageDiff diff = rl::compare_images(renderer.frame(), peer_frame, 8);
        std::printf(
            "llvmpipe (%s) on %d threads: median %.2f ms per frame; ours takes %.2fx its time; "
            "%.3f%% of pixels differ by more than 8/255\n",
            llvmpipe->version().c_str(), renderer.threads(), peer_ms, ms / peer_ms,
            100.0 * diff.share_over);
        if (!peer_output.empty()) outputs.stage(peer_output, peer_frame);
        outputs.commit();
        return 0;
    });
}
