// imgdiff: compares two images and says whether they agree within the given
// tolerances. Exit code 0: within tolerance; 1: not; 2: could not compare.
#include "rasterlab/cli.hpp"

#include <cstdio>
#include <iostream>

#include "rasterlab/image_io.hpp"
#include "rasterlab/image_metrics.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Compare two images (TGA, PNG, JPG): prints the largest channel difference, "
        "the share of differing pixels and the PSNR; fails when a tolerance is exceeded."};
    std::string expected_path, actual_path, diff_path;
    int max_abs = 0, threshold = 0;
    double max_share = 0.0, min_psnr = 0.0;
    app.add_option("expected", expected_path, "Reference image")->required();
    app.add_option("actual", actual_path, "Image to check")->required();
    app.add_option("--max-abs", max_abs, "Largest channel difference allowed (0..255)")
        ->capture_default_str()
        ->check(rl::range(0, 255));
    app.add_option("--threshold", threshold,
                   "A pixel differs when its largest channel difference exceeds this")
        ->capture_default_str()
        ->check(rl::range(0, 255));
    app.add_option("--max-share", max_share, "Share of differing pixels allowed (0..1)")
        ->capture_default_str()
        ->check(rl::finite_number(0.0, 1.0));  // CLI::Range lets NaN through
    app.add_option("--min-psnr", min_psnr, "Smallest PSNR allowed in dB (0 = no limit)")
        ->capture_default_str()
        ->check(rl::finite_number(0.0, 1000.0));
    app.add_option("--diff", diff_path, "Where to write a difference image when the check fails");
    std::string overlay_path;
    app.add_option("--overlay", overlay_path,
                   "Always write ACTUAL dimmed, with the pixels that differ by more than "
                   "--threshold painted magenta (for the docs' failure pictures)");
    if (const auto exit = app.parse(argc, argv)) return *exit;

    return rl::guarded_main(
        "imgdiff",
        [&] {
            const rl::Image expected = rl::load_image(expected_path);
            const rl::Image actual = rl::load_image(actual_path);
            if (expected.width() != actual.width() || expected.height() != actual.height()) {
                std::cout << "size differs: expected " << expected.width() << "x"
                          << expected.height() << ", got " << actual.width() << "x"
                          << actual.height() << "\n";
                return 1;
            }
            const rl::ImageDiff d = rl::compare_images(expected, actual, threshold);
            if (!overlay_path.empty()) {
                rl::save_image(overlay_path, rl::difference_overlay(expected, actual, threshold));
                std::printf("overlay written to %s\n", overlay_path.c_str());
            }
            std::printf("max abs difference %d (allowed %d)\n", d.max_abs, max_abs);
            std::printf("differing pixels %.6f%% (difference > %d; allowed %.6f%%)\n",
                        100.0 * d.share_over, threshold, 100.0 * max_share);
            std::printf("mean abs %.4f, RMSE %.4f, PSNR %.2f dB (required %.2f dB)\n", d.mean_abs,
                        d.rmse, d.psnr, min_psnr);
            const bool ok = d.max_abs <= max_abs && d.share_over <= max_share && d.psnr >= min_psnr;
            if (!ok && !diff_path.empty()) {
                rl::save_image(diff_path, rl::difference_image(expected, actual, threshold));
                std::printf("difference image written to %s\n", diff_path.c_str());
            }
            std::printf("%s\n", ok ? "MATCH" : "MISMATCH");
            return ok ? 0 : 1;
        },
        2);
}
