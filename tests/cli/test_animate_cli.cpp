// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_animate_cli.cpp
 *  `lagrange animate`: the HTML player's embedded frames against the simulation, its rods
 *  and controls, the error without ffmpeg, and an extension nothing writes; a free body's
 *  Poinsot construction in the player; MP4 and GIF decoded by ffprobe and ffmpeg (frame
 *  count, duration, size, and the bob's pixels where the trajectory puts it); the player
 *  opened in headless Chromium at #t=2.5 (paused there, the bobs drawn where the simulation
 *  has them) and playing. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace lagrange_test;

namespace {

const std::string scene_text = "scene \"Double pendulum\"\nparameters m l g\ncoordinates theta phi\n"
                               "point upper mass m at (l*sin(theta), -l*cos(theta))\n"
                               "point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
                               "gravity g along (0, -1)\nvalues m = 1, l = 1.5, g = 9.81\n"
                               "initial theta = 1, phi = 2\nsimulate until 3 step 0.1\n";

/// The JSON of the page's `lagrange-data` element.
nlohmann::json page_data(const std::string& html)
{
    const std::string open = "<script id=\"lagrange-data\" type=\"application/json\">";
    const std::size_t begin = html.find(open);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = html.find("</script>", begin);
    return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

constexpr double length = 1.5;

/// What a shell command prints on standard output.
std::string command_output(const std::string& command)
{
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
        out.append(buffer, n);
    pclose(pipe);
    return out;
}

/// θ and φ at time t from `lagrange simulate --csv` (its rows at every 0.1).
std::array<double, 2> simulated_angles(const std::string& csv_path, double t)
{
    std::istringstream rows(read_file(csv_path));
    std::string line;
    std::getline(rows, line);
    while (std::getline(rows, line)) {
        double time, theta, phi;
        REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf", &time, &theta, &phi) == 3);
        if (std::abs(time - t) < 1e-9)
            return {theta, phi};
    }
    FAIL("no row at t = " << t);
    return {};
}

/// The value of the attribute `name="…"` in `dom` (empty when absent), with &quot; undone.
std::string attribute(const std::string& dom, const std::string& name)
{
    const std::size_t begin = dom.find(name + "=\"");
    if (begin == std::string::npos)
        return "";
    const std::size_t from = begin + name.size() + 2, end = dom.find('"', from);
    std::string value = dom.substr(from, end - from);
    for (std::size_t k; (k = value.find("&quot;")) != std::string::npos;)
        value.replace(k, 6, "\"");
    return value;
}

std::string chromium_dom(const std::string& url, int budget_ms)
{
    return command_output("timeout 120 chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=" +
                          std::to_string(budget_ms) + " --dump-dom '" + url + "' 2>/dev/null");
}

} // namespace

TEST_CASE("cli: animate writes a self-contained player whose frames are the simulation's", "[cli][animate]")
{
    const std::string scene = temporary_file("animated.lag", scene_text);
    const std::string html = temporary_file("animated.html", "");
    const std::string csv = temporary_file("animated.csv", "");
    cli_result drawn = run_cli("animate " + scene + " --fps 10 --trail 1 -o " + html, "", 60);
    REQUIRE(drawn.exit_code == 0);
    cli_result simulated = run_cli("simulate " + scene + " --csv " + csv, "", 60);
    REQUIRE(simulated.exit_code == 0);
    const std::string page = read_file(html);
    // Self-contained: nothing is loaded from elsewhere.
    CHECK(page.find("src=") == std::string::npos);
    CHECK(page.find("http") == std::string::npos);
    CHECK(page.find("location.hash") != std::string::npos);
    CHECK(page.find("lagrangePlayer") != std::string::npos);
    const nlohmann::json data = page_data(page);
    CHECK(data["view"] == "xy");
    CHECK(data["trail"] == 1);
    const std::size_t frames = data["times"].size(), markers = data["markers"].size();
    REQUIRE(frames == 31);
    REQUIRE(markers == 3); // upper, lower, the pivot
    CHECK(data["markers"][2]["name"] == "pivot");
    // Rods: upper to the pivot and lower to upper, which keep their distance; not lower to the pivot.
    CHECK(data["rods"] == nlohmann::json::parse("[[0,1],[0,2]]"));
    // The simulation's CSV (t, theta, phi, …) at the same times: the bobs where it says.
    std::istringstream rows(read_file(csv));
    std::string line;
    std::getline(rows, line); // header
    double worst = 0;
    for (std::size_t f = 0; f < frames && std::getline(rows, line); ++f) {
        double t, theta, phi;
        REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &theta, &phi) == 3);
        CHECK(std::abs(data["times"][f].get<double>() - t) <= 1e-12);
        const double l = 1.5;
        const double expected[4] = {l * std::sin(theta), -l * std::cos(theta), l * std::sin(theta) + l * std::sin(phi),
                                    -l * std::cos(theta) - l * std::cos(phi)};
        const auto& p = data["positions"];
        const double got[4] = {p[f * 9 + 0], p[f * 9 + 1], p[f * 9 + 3], p[f * 9 + 4]};
        for (int k = 0; k < 4; ++k)
            worst = std::max(worst, std::abs(got[k] - expected[k]));
    }
    CHECK(worst <= 1e-7);
    // The energy drift is shown, and is small.
    REQUIRE(data["drift"].size() == frames);
    for (const auto& d : data["drift"])
        CHECK(std::abs(d.get<double>()) <= 1e-7);
}

TEST_CASE("cli: animate says when ffmpeg is missing, and refuses an extension nothing writes", "[cli][animate]")
{
    const std::string scene = temporary_file("animated.lag", scene_text);
    // A PATH that holds only `timeout` (which the runner needs): no ffmpeg, no compiler.
    const std::string keep = temporary_file("keep", "");
    const std::string folder = keep.substr(0, keep.rfind('/')) + "/only_timeout";
    cli_result video = run_cli("animate " + scene + " -o " + folder + "/out.mp4", "", 30,
                               "mkdir -p " + folder + " && ln -sf \"$(command -v timeout)\" " + folder +
                                   "/timeout && export PATH=" + folder);
    CHECK(video.exit_code == 1);
    CHECK_THAT(video.err, Catch::Contains("ffmpeg is not installed (Debian package ffmpeg)"));
    cli_result other = run_cli("animate " + scene + " -o " + folder + "/out.avi");
    CHECK(other.exit_code == 2);
    CHECK_THAT(other.err, Catch::Contains("takes a file ending in .html, .mp4 or .gif"));
    cli_result view = run_cli("animate " + scene + " --view yz -o " + folder + "/out.html");
    CHECK(view.exit_code == 2);
    // More frames than a page or a video holds: a message, before any integration.
    cli_result endless = run_cli("animate " + scene + " --until 1e9 -o " + folder + "/out.html");
    CHECK(endless.exit_code == 1);
    CHECK_THAT(endless.err, Catch::Contains("more than a million: shorten it (--until)"));
}

TEST_CASE("cli: phase draws the pendulum's portrait with its separatrix, and refuses an unknown coordinate",
          "[cli][phase][gnuplot]")
{
    const std::string scene = temporary_file(
        "pendulum.lag", "parameters m l g\ncoordinates theta\npoint P mass m at (l*sin(theta), -l*cos(theta))\n"
                        "gravity g along (0, -1)\nvalues m = 1, l = 1, g = 9.81\n");
    const std::string svg = temporary_file("phase.svg", "");
    cli_result drawn = run_cli("phase " + scene + " -o " + svg, "", 60);
    REQUIRE(drawn.exit_code == 0);
    CHECK_THAT(drawn.err, Catch::Contains("separatrices at energies 9.81"));
    const std::string picture = read_file(svg);
    CHECK(picture.find("<svg") != std::string::npos);
    CHECK(picture.find("separatrices") != std::string::npos);
    cli_result unknown = run_cli("phase " + scene + " --coordinate psi -o " + svg);
    CHECK(unknown.exit_code == 2);
    CHECK_THAT(unknown.err, Catch::Contains("--coordinate:1:1: error: `psi` is not a coordinate"));
}

TEST_CASE("cli: animate draws a free body by Poinsot's construction", "[cli][animate]")
{
    const std::string scene = temporary_file(
        "free_box.lag", "parameters M a b c\nbody X box(a, b, c) mass M\nomega X (w1, w2, w3)\n"
                        "values M = 1, a = 1, b = 2, c = 3\ninitial w1 = 0.2, w2 = 1, w3 = 0.3\nsimulate until 5\n");
    const std::string html = temporary_file("free_box.html", "");
    cli_result drawn = run_cli("animate " + scene + " --fps 10 -o " + html, "", 60);
    REQUIRE(drawn.exit_code == 0);
    const nlohmann::json data = page_data(read_file(html));
    CHECK(data["view"] == "3d");
    REQUIRE(data["times"].size() == 51);
    const auto& p = data["poinsot"];
    REQUIRE(p["rotation"].size() == 51 * 9);
    REQUIRE(p["contact"].size() == 51 * 3);
    // The contact point stays on the plane z = −√(2T)/|L| (T, L from ω(0) by hand).
    const std::array<double, 3> I{13.0 / 12, 10.0 / 12, 5.0 / 12}, w0{0.2, 1, 0.3};
    double two_t = 0, l2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        two_t += I[k] * w0[k] * w0[k];
        l2 += I[k] * I[k] * w0[k] * w0[k];
    }
    const double distance = std::sqrt(two_t / l2);
    CHECK(std::abs(p["distance"].get<double>() - distance) <= 1e-14);
    for (std::size_t f = 0; f < 51; ++f)
        CHECK(std::abs(p["contact"][3 * f + 2].get<double>() + distance) <= 1e-9);
    for (const auto& d : data["drift"])
        CHECK(std::abs(d.get<double>()) <= 1e-9);
}

TEST_CASE("cli: animate encodes MP4 and GIF at real time with the bob where the trajectory says",
          "[cli][animate][ffmpeg]")
{
    const std::string scene = temporary_file("video.lag", scene_text);
    const std::string mp4 = temporary_file("video.mp4", ""), gif = temporary_file("video.gif", "");
    const std::string html = temporary_file("video.html", "");
    // 10 frames per second of video, at twice real time: a frame every 0.2 of simulated time.
    cli_result encoded = run_cli("animate " + scene + " --fps 10 --speed 2 -o " + mp4, "", 120);
    REQUIRE(encoded.exit_code == 0);
    const std::string probe =
        command_output("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                       "stream=width,height,nb_read_frames,codec_name -show_entries format=duration -of "
                       "default=noprint_wrappers=1 " + mp4);
    CHECK_THAT(probe, Catch::Contains("codec_name=h264"));
    CHECK_THAT(probe, Catch::Contains("width=640"));
    CHECK_THAT(probe, Catch::Contains("height=480"));
    CHECK_THAT(probe, Catch::Contains("nb_read_frames=16")); // t = 0, 0.2, …, 3
    double duration = 0;
    REQUIRE(std::sscanf(probe.substr(probe.find("duration=")).c_str(), "duration=%lf", &duration) == 1);
    CHECK(std::abs(duration - 1.6) <= 0.05);

    // Frame 8 (t = 1.6) decoded to RGB: the lower bob's disc is where the simulation puts it,
    // in the picture's framing (every marker at every frame fits 80% of the smaller side).
    const std::string rgb = temporary_file("frame.rgb", "");
    REQUIRE(std::system(("ffmpeg -v error -y -i " + mp4 + " -vf 'select=eq(n\\,8)' -frames:v 1 -f rawvideo -pix_fmt rgb24 " +
                         rgb).c_str()) == 0);
    const std::string pixels = read_file(rgb);
    REQUIRE(pixels.size() == 640u * 480u * 3u);
    REQUIRE(run_cli("animate " + scene + " --fps 5 -o " + html, "", 60).exit_code == 0);
    const nlohmann::json data = page_data(read_file(html));
    REQUIRE(data["times"].size() == 16);
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (std::size_t f = 0; f < 16; ++f)
        for (std::size_t m = 0; m < 3; ++m)
            for (std::size_t k = 0; k < 2; ++k) {
                const double x = data["positions"][(f * 3 + m) * 3 + k];
                lo[k] = std::min(lo[k], x);
                hi[k] = std::max(hi[k], x);
            }
    const double scale = 0.8 * 480 / std::max(hi[0] - lo[0], hi[1] - lo[1]);
    const std::string csv = temporary_file("video.csv", "");
    REQUIRE(run_cli("simulate " + scene + " --csv " + csv, "", 60).exit_code == 0);
    const auto [theta, phi] = simulated_angles(csv, 1.6);
    const double x = length * std::sin(theta) + length * std::sin(phi), y = -length * std::cos(theta) - length * std::cos(phi);
    const double column = 320 + (x - (lo[0] + hi[0]) / 2) * scale, row = 240 - (y - (lo[1] + hi[1]) / 2) * scale;
    // The centre of the red pixels (the bobs' colour, #d62728) within 25 pixels of there.
    double sum_c = 0, sum_r = 0, count = 0;
    for (int r = 0; r < 480; ++r)
        for (int c = 0; c < 640; ++c) {
            if (std::hypot(c - column, r - row) > 25)
                continue;
            const auto* px = reinterpret_cast<const unsigned char*>(pixels.data()) + (r * 640 + c) * 3;
            if (px[0] > 180 && px[1] < 90 && px[2] < 90) {
                sum_c += c;
                sum_r += r;
                ++count;
            }
        }
    REQUIRE(count >= 100); // a disc of radius 20 has about 1,250 pixels
    CHECK(std::hypot(sum_c / count - column, sum_r / count - row) <= 3);

    cli_result animated = run_cli("animate " + scene + " --fps 10 --speed 2 --trail 1 -o " + gif, "", 120);
    REQUIRE(animated.exit_code == 0);
    const std::string gif_probe = command_output("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                                 "stream=width,height,nb_read_frames,codec_name -show_entries "
                                                 "format=duration -of default=noprint_wrappers=1 " + gif);
    CHECK_THAT(gif_probe, Catch::Contains("codec_name=gif"));
    CHECK_THAT(gif_probe, Catch::Contains("width=640"));
    CHECK_THAT(gif_probe, Catch::Contains("nb_read_frames=16"));
    double gif_duration = 0;
    REQUIRE(std::sscanf(gif_probe.substr(gif_probe.find("duration=")).c_str(), "duration=%lf", &gif_duration) == 1);
    CHECK(std::abs(gif_duration - 1.6) <= 0.05); // GIF delays are in hundredths of a second
}

TEST_CASE("cli: the player opens paused at #t=2.5 with the bobs where the simulation has them, and plays",
          "[cli][animate][chromium]")
{
    const std::string scene = temporary_file("browser.lag", scene_text);
    const std::string html = temporary_file("browser.html", ""), csv = temporary_file("browser.csv", "");
    REQUIRE(run_cli("animate " + scene + " --fps 10 -o " + html, "", 60).exit_code == 0);
    REQUIRE(run_cli("simulate " + scene + " --csv " + csv, "", 60).exit_code == 0);
    std::array<std::string, 2> screens;
    for (double t : {2.5, 1.0}) {
        std::ostringstream url;
        url << "file://" << html << "#t=" << t;
        const std::string dom = chromium_dom(url.str(), 1000);
        REQUIRE(dom.find("id=\"stage\"") != std::string::npos);
        CHECK(std::stod(attribute(dom, "data-time")) == t);
        CHECK(attribute(dom, "data-playing") == "false");
        const nlohmann::json world = nlohmann::json::parse(attribute(dom, "data-world"));
        REQUIRE(world.size() == 3); // upper, lower, the pivot
        const auto [theta, phi] = simulated_angles(csv, t);
        const double expected[2][2] = {{length * std::sin(theta), -length * std::cos(theta)},
                                       {length * std::sin(theta) + length * std::sin(phi),
                                        -length * std::cos(theta) - length * std::cos(phi)}};
        for (std::size_t m = 0; m < 2; ++m)
            for (std::size_t k = 0; k < 2; ++k)
                CHECK(std::abs(world[m][k].get<double>() - expected[m][k]) <= 1e-7);
        screens[t == 1.0] = attribute(dom, "data-screen");
    }
    // Two moments, two pictures: the bobs are drawn at other pixels, and the screenshots differ.
    CHECK(screens[0] != screens[1]);
    std::array<std::string, 2> shots;
    for (std::size_t k = 0; k < 2; ++k) {
        const std::string png = temporary_file("shot" + std::to_string(k) + ".png", "");
        command_output("timeout 120 chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=1000 "
                       "--window-size=700,700 --screenshot=" + png + " 'file://" + html + (k ? "#t=1" : "#t=2.5") +
                       "' 2>/dev/null");
        shots[k] = read_file(png);
        REQUIRE(shots[k].compare(1, 3, "PNG") == 0);
    }
    CHECK(shots[0] != shots[1]);
    // Without a time in the address it plays: after 1.5 s (virtual time) the clock has moved.
    const std::string playing = chromium_dom("file://" + html, 1500);
    const double t = std::stod(attribute(playing, "data-time"));
    CHECK(t >= 1.0);
    CHECK(t <= 2.0);
    CHECK(attribute(playing, "data-playing") == "true");
}

namespace {

/// Two uniform rods (examples/compound_double_pendulum.lag): the lower one hangs from the
/// upper one's end, th2 relative to it.
const std::string rods_text = "scene \"Compound double pendulum\"\nparameters m l g\ncoordinates th1 th2\n"
                              "body upper stick(l) mass m axis y at (l/2*sin(th1), -l/2*cos(th1), 0) "
                              "orientation rotations(z th1)\n"
                              "body lower stick(l) mass m axis y attached to upper "
                              "at (l/2*sin(th2), -l/2 - l/2*cos(th2), 0) orientation rotations(z th2)\n"
                              "gravity g along (0, -1, 0)\nvalues m = 1, l = 1.5, g = 9.81\n"
                              "initial th1 = 1.2, th2 = -0.4\nsimulate until 2 step 0.1\n";

/// The scene's picture frame in the xy view, as the writers fit it: every named marker and
/// every point of the bodies' outlines at every frame, 80% of the smaller side.
struct framing {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300}, scale = 1;
    std::array<double, 2> pixel(double x, double y, int width, int height) const
    {
        return {width / 2.0 + (x - (lo[0] + hi[0]) / 2) * scale, height / 2.0 - (y - (lo[1] + hi[1]) / 2) * scale};
    }
};

framing page_framing(const nlohmann::json& data, int smaller_side)
{
    framing f;
    const std::size_t frames = data["times"].size(), markers = data["markers"].size(), bodies = data["bodies"].size();
    auto include = [&](double x, double y) {
        f.lo[0] = std::min(f.lo[0], x), f.hi[0] = std::max(f.hi[0], x);
        f.lo[1] = std::min(f.lo[1], y), f.hi[1] = std::max(f.hi[1], y);
    };
    for (std::size_t n = 0; n < frames; ++n) {
        for (std::size_t m = 0; m < markers; ++m)
            if (!data["markers"][m]["name"].get<std::string>().empty())
                include(data["positions"][(n * markers + m) * 3], data["positions"][(n * markers + m) * 3 + 1]);
        for (std::size_t b = 0; b < bodies; ++b) {
            const std::size_t c = data["bodies"][b]["centre"];
            const double cx = data["positions"][(n * markers + c) * 3], cy = data["positions"][(n * markers + c) * 3 + 1];
            const auto& R = data["rotations"];
            const std::size_t r0 = (n * bodies + b) * 9;
            for (const auto& line : data["bodies"][b]["outline"])
                for (std::size_t k = 0; k + 2 < line.size(); k += 3) {
                    const double x = line[k], y = line[k + 1], z = line[k + 2];
                    include(cx + R[r0].get<double>() * x + R[r0 + 1].get<double>() * y + R[r0 + 2].get<double>() * z,
                            cy + R[r0 + 3].get<double>() * x + R[r0 + 4].get<double>() * y + R[r0 + 5].get<double>() * z);
                }
        }
    }
    f.scale = 0.8 * smaller_side / std::max(f.hi[0] - f.lo[0], f.hi[1] - f.lo[1]);
    return f;
}

} // namespace

TEST_CASE("cli: animate draws placed rigid bodies by shape and pivot in the page's data", "[cli][animate]")
{
    // The heavy top: a body given by its inertia is drawn as the ellipsoid of the uniform solid
    // with the same moments (semi-axes sqrt(5 (I_j + I_k - I_i) / 2M)), held by a rod to the
    // pivot it turns about; the compound pendulum's rods as sticks of length l.
    const std::string top = std::string(LAGRANGE_SOURCE_DIR) + "/examples/heavy_top.lag";
    const std::string html = temporary_file("top.html", "");
    REQUIRE(run_cli("animate " + top + " --until 1 --fps 10 -o " + html, "", 60).exit_code == 0);
    const nlohmann::json data = page_data(read_file(html));
    REQUIRE(data["bodies"].size() == 1);
    CHECK(data["bodies"][0]["shape"] == "inertia ellipsoid");
    // A = 0.3, C = 0.2, M = 1: semi-axes sqrt(5 C / 2) = 0.7071 (twice) and sqrt(5 (2A - C) / 2) = 1.
    CHECK(std::abs(data["bodies"][0]["size"].get<double>() - 1) <= 1e-9);
    const std::size_t markers = data["markers"].size(), centre = data["bodies"][0]["centre"];
    bool pivot = false;
    for (std::size_t m = 0; m < markers; ++m)
        pivot = pivot || data["markers"][m]["name"] == "pivot";
    CHECK(pivot);
    bool stem = false;
    for (const auto& rod : data["rods"])
        stem = stem || (rod[0] == centre && data["markers"][rod[1].get<std::size_t>()]["name"] == "pivot");
    CHECK(stem);
    // Each frame's rotation is zxz(φ, θ, ψ) of the simulation: its third column (the symmetry
    // axis) points from the pivot to the centre of mass, at distance l = 0.5.
    for (std::size_t f = 0; f < data["times"].size(); ++f) {
        const auto& R = data["rotations"];
        for (int k = 0; k < 3; ++k)
            CHECK(std::abs(R[f * 9 + 3 * k + 2].get<double>() * 0.5 -
                           data["positions"][(f * markers + centre) * 3 + k].get<double>()) <= 1e-9);
    }

    const std::string rods = temporary_file("rods.lag", rods_text), rods_html = temporary_file("rods.html", "");
    REQUIRE(run_cli("animate " + rods + " -o " + rods_html, "", 60).exit_code == 0);
    const nlohmann::json pair = page_data(read_file(rods_html));
    REQUIRE(pair["bodies"].size() == 2);
    for (const auto& body : pair["bodies"]) {
        CHECK(body["shape"] == "stick");
        CHECK(std::abs(body["size"].get<double>() - 0.75) <= 1e-12);
    }
    CHECK(pair["view"] == "xy"); // the sticks stay in the plane
    // The upper stick reaches the pivot itself: a pivot, and no rod to its centre.
    bool pair_pivot = false;
    for (const auto& marker : pair["markers"])
        pair_pivot = pair_pivot || marker["name"] == "pivot";
    CHECK(pair_pivot);
    CHECK(pair["rods"].empty());
    // The ground through the pivot, normal to gravity (0, -1, 0): u and v in the xz plane.
    REQUIRE(pair.contains("ground"));
    for (const char* axis : {"u", "v"}) {
        CHECK(std::abs(pair["ground"][axis][1].get<double>()) <= 1e-15);
        CHECK(std::abs(std::hypot(pair["ground"][axis][0].get<double>(), pair["ground"][axis][2].get<double>()) - 1) <=
              1e-15);
    }
    CHECK(pair["ground"]["half"].get<double>() > 0);
    // The heavy top's ground is normal to (0, 0, -1).
    REQUIRE(data.contains("ground"));
    CHECK(std::abs(data["ground"]["u"][2].get<double>()) <= 1e-15);
    CHECK(std::abs(data["ground"]["v"][2].get<double>()) <= 1e-15);
}

TEST_CASE("cli: animate draws a moving support and ties the point to it", "[cli][animate]")
{
    // The Kapitza pendulum: the bob at (l sin φ, a cos γt − l cos φ) hangs from the support
    // (0, a cos γt), which moves with t alone (a = 0.05, γ = 120, l = 1).
    const std::string html = temporary_file("kapitza.html", "");
    REQUIRE(run_cli("animate " + std::string(LAGRANGE_SOURCE_DIR) + "/examples/kapitza_pendulum.lag --values gamma=120 --until 0.5 "
                    "--fps 40 -o " + html, "", 60).exit_code == 0);
    const nlohmann::json data = page_data(read_file(html));
    const std::size_t markers = data["markers"].size();
    std::size_t support = markers;
    for (std::size_t m = 0; m < markers; ++m)
        if (data["markers"][m]["name"] == "support")
            support = m;
    REQUIRE(support < markers);
    REQUIRE(data["rods"].size() == 1);
    CHECK(data["rods"][0][0] == 0);
    CHECK(data["rods"][0][1] == support);
    for (std::size_t f = 0; f < data["times"].size(); ++f) {
        const double t = data["times"][f];
        CHECK(std::abs(data["positions"][(f * markers + support) * 3].get<double>()) <= 1e-15);
        CHECK(std::abs(data["positions"][(f * markers + support) * 3 + 1].get<double>() - 0.05 * std::cos(120 * t)) <=
              1e-12);
    }
}

TEST_CASE("cli: animate's video draws each rod's tip and axis where the simulation's orientation puts them",
          "[cli][animate][ffmpeg]")
{
    const std::string scene = temporary_file("rods_video.lag", rods_text);
    const std::string mp4 = temporary_file("rods.mp4", ""), html = temporary_file("rods_video.html", "");
    const std::string csv = temporary_file("rods.csv", ""), rgb = temporary_file("rods_frame.rgb", "");
    REQUIRE(run_cli("animate " + scene + " --fps 10 -o " + mp4, "", 120).exit_code == 0);
    REQUIRE(run_cli("animate " + scene + " --fps 10 -o " + html, "", 60).exit_code == 0);
    REQUIRE(run_cli("simulate " + scene + " --csv " + csv, "", 60).exit_code == 0);
    const framing frame = page_framing(page_data(read_file(html)), 480);
    REQUIRE(std::system(("ffmpeg -v error -y -i " + mp4 +
                         " -vf 'select=eq(n\\,13)' -frames:v 1 -f rawvideo -pix_fmt rgb24 " + rgb).c_str()) == 0);
    const std::string pixels = read_file(rgb);
    REQUIRE(pixels.size() == 640u * 480u * 3u);
    auto pixel = [&](int c, int r) {
        return reinterpret_cast<const unsigned char*>(pixels.data()) + (r * 640 + c) * 3;
    };
    // Whether a pixel of the given test lies within `radius` pixels of (column, row).
    auto near = [&](std::array<double, 2> at, double radius, const auto& is) {
        for (int r = static_cast<int>(at[1] - radius); r <= static_cast<int>(at[1] + radius); ++r)
            for (int c = static_cast<int>(at[0] - radius); c <= static_cast<int>(at[0] + radius); ++c)
                if (r >= 0 && r < 480 && c >= 0 && c < 640 && std::hypot(c - at[0], r - at[1]) <= radius &&
                    is(pixel(c, r)))
                    return true;
        return false;
    };
    auto rod_blue = [](const unsigned char* p) { return p[2] > 140 && p[0] < 100 && p[1] > 40 && p[1] < 150; };
    auto purple = [](const unsigned char* p) { return p[0] > 110 && p[2] > 150 && p[1] < 140 && p[0] < 190; };
    // Frame 13: t = 1.3. The rods' ends and axis 1 in closed form from the simulated angles.
    const auto [th1, th2] = simulated_angles(csv, 1.3);
    const double l = 1.5, a = th1 + th2;
    const double hinge[2] = {l * std::sin(th1), -l * std::cos(th1)};
    const double tip[2] = {hinge[0] + l * std::sin(a), hinge[1] - l * std::cos(a)};
    const double lower_centre[2] = {hinge[0] + l / 2 * std::sin(a), hinge[1] - l / 2 * std::cos(a)};
    const std::array<double, 2> tip_pixel = frame.pixel(tip[0], tip[1], 640, 480);
    INFO("the lower rod's tip at pixel (" << tip_pixel[0] << ", " << tip_pixel[1] << ")");
    CHECK(near(tip_pixel, 4, rod_blue));
    // Beyond the tip, along the rod, there is no rod.
    const double beyond = 14 / frame.scale;
    CHECK(!near(frame.pixel(tip[0] + beyond * std::sin(a), tip[1] - beyond * std::cos(a), 640, 480), 4, rod_blue));
    // Along the rod, three quarters down.
    CHECK(near(frame.pixel(hinge[0] + 0.75 * l * std::sin(a), hinge[1] - 0.75 * l * std::cos(a), 640, 480), 3, rod_blue));
    // Body axis 1 of the lower rod, R e1 = (cos a, sin a), drawn 0.75 × l/2 from its centre:
    // purple near its far end, not on the other side.
    const double reach = 0.75 * l / 2 * 0.9;
    CHECK(near(frame.pixel(lower_centre[0] + reach * std::cos(a), lower_centre[1] + reach * std::sin(a), 640, 480), 3,
               purple));
    CHECK(!near(frame.pixel(lower_centre[0] - reach * std::cos(a), lower_centre[1] - reach * std::sin(a), 640, 480), 3,
                purple));
    // The pivot: black at the origin.
    CHECK(near(frame.pixel(0, 0, 640, 480), 3, [](const unsigned char* p) { return p[0] < 40 && p[1] < 40 && p[2] < 40; }));
}

TEST_CASE("cli: the player draws placed bodies at the simulation's pose", "[cli][animate][chromium]")
{
    const std::string scene = temporary_file("rods_browser.lag", rods_text);
    const std::string html = temporary_file("rods_browser.html", ""), csv = temporary_file("rods_browser.csv", "");
    REQUIRE(run_cli("animate " + scene + " --fps 10 -o " + html, "", 60).exit_code == 0);
    REQUIRE(run_cli("simulate " + scene + " --csv " + csv, "", 60).exit_code == 0);
    std::array<std::string, 2> shots;
    for (double t : {0.7, 1.6}) {
        std::ostringstream url;
        url << "file://" << html << "#t=" << t;
        const std::string dom = chromium_dom(url.str(), 1000);
        REQUIRE(dom.find("id=\"stage\"") != std::string::npos);
        CHECK(attribute(dom, "data-playing") == "false");
        const nlohmann::json turns = nlohmann::json::parse(attribute(dom, "data-rotations"));
        REQUIRE(turns.size() == 2);
        const auto [th1, th2] = simulated_angles(csv, t);
        // R = R_z(th1) for the upper rod, R_z(th1 + th2) for the lower one (its angle is relative).
        for (std::size_t b = 0; b < 2; ++b) {
            const double a = b == 0 ? th1 : th1 + th2;
            const double expected[9] = {std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1};
            for (std::size_t k = 0; k < 9; ++k)
                CHECK(std::abs(turns[b][k].get<double>() - expected[k]) <= 1e-7);
        }
        // The centres of mass among the drawn markers, where the simulation has them.
        const nlohmann::json world = nlohmann::json::parse(attribute(dom, "data-world"));
        REQUIRE(world.size() >= 2);
        CHECK(std::abs(world[0][0].get<double>() - 0.75 * std::sin(th1)) <= 1e-7);
        CHECK(std::abs(world[1][0].get<double>() - (1.5 * std::sin(th1) + 0.75 * std::sin(th1 + th2))) <= 1e-7);
        const std::string png = temporary_file("rods_shot.png", "");
        std::ostringstream shot;
        shot << "timeout 120 chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=1000 "
                "--window-size=700,700 --screenshot=" << png << " '" << url.str() << "' 2>/dev/null";
        command_output(shot.str());
        shots[t > 1] = read_file(png);
        REQUIRE(shots[t > 1].compare(1, 3, "PNG") == 0);
    }
    CHECK(shots[0] != shots[1]);
}

TEST_CASE("cli: animate runs a scene with constraints as simulate does and keeps the rod", "[cli][animate]")
{
    // A pendulum in Cartesian coordinates held by the constraint x² + y² = l² (l = 2): every
    // frame on the circle, the rod to the pivot drawn, and the frames where `simulate` puts the bob.
    const std::string scene = temporary_file("rod.lag", "scene \"Rod pendulum\"\nparameters m g l\ncoordinates x y\n"
                                                        "point P mass m at (x, y)\ngravity g along (0, -1)\n"
                                                        "constraint rod: x^2 + y^2 = l^2\nvalues m = 1, g = 9.81, l = 2\n"
                                                        "initial x = 1.2, y = -1.6\nsimulate until 2 step 0.1\n");
    const std::string html = temporary_file("rod.html", ""), csv = temporary_file("rod.csv", "");
    REQUIRE(run_cli("animate " + scene + " --fps 10 -o " + html, "", 60).exit_code == 0);
    REQUIRE(run_cli("simulate " + scene + " --csv " + csv, "", 60).exit_code == 0);
    const nlohmann::json data = page_data(read_file(html));
    REQUIRE(data["times"].size() == 21);
    REQUIRE(data["rods"].size() == 1);
    const std::size_t markers = data["markers"].size();
    CHECK(data["markers"][data["rods"][0][1].get<std::size_t>()]["name"] == "pivot");
    std::istringstream rows(read_file(csv));
    std::string line;
    std::getline(rows, line);
    std::size_t compared = 0;
    while (std::getline(rows, line)) {
        double t, x, y;
        REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &x, &y) == 3);
        const std::size_t f = static_cast<std::size_t>(std::lround(t * 10));
        const double px = data["positions"][f * markers * 3], py = data["positions"][f * markers * 3 + 1];
        CHECK(std::abs(std::hypot(px, py) - 2) <= 1e-9);
        CHECK(std::abs(px - x) <= 1e-6);
        CHECK(std::abs(py - y) <= 1e-6);
        ++compared;
    }
    CHECK(compared == 21);
    for (const auto& drift : data["drift"])
        CHECK(std::abs(drift.get<double>()) <= 1e-7);

    // Off the constraints: bad input at the value, as for simulate; --project-initial starts on them.
    const std::string off = temporary_file("rod_off.lag", "scene \"Rod pendulum\"\nparameters m g l\ncoordinates x y\n"
                                                          "point P mass m at (x, y)\ngravity g along (0, -1)\n"
                                                          "constraint rod: x^2 + y^2 = l^2\nvalues m = 1, g = 9.81, l = 2\n"
                                                          "initial x = 1.2, y = -1.5\nsimulate until 1\n");
    cli_result refused = run_cli("animate " + off + " -o " + html, "", 60);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.err, Catch::Contains(":8:22: error: the initial state is off the constraints (`rod` by 0.31)"));
    CHECK_THAT(refused.err, Catch::Contains("initial x = 1.2, y = -1.5\n                     ^"));
    REQUIRE(run_cli("animate " + off + " --project-initial -o " + html, "", 60).exit_code == 0);
    const nlohmann::json projected = page_data(read_file(html));
    for (std::size_t f = 0; f < projected["times"].size(); ++f)
        CHECK(std::abs(std::hypot(projected["positions"][f * projected["markers"].size() * 3].get<double>(),
                                  projected["positions"][f * projected["markers"].size() * 3 + 1].get<double>()) -
                       2) <= 1e-9);
}

TEST_CASE("cli: animate draws the ground a body rolls on and none under a falling one", "[cli][animate]")
{
    // The rolling coin has no pivot: its disk's lowest point stays at z = 0 (to the outline's
    // sampling), so the ground is the plane z = 0, normal to gravity (0, 0, -1), under the whole path.
    const std::string html = temporary_file("coin.html", "");
    REQUIRE(run_cli("animate " + std::string(LAGRANGE_SOURCE_DIR) + "/examples/rolling_coin.lag -o " + html +
                        " --until 2",
                    "", 120)
                .exit_code == 0);
    const nlohmann::json data = page_data(read_file(html));
    REQUIRE(data.contains("ground"));
    const auto& ground = data["ground"];
    CHECK(std::abs(ground["centre"][2].get<double>()) <= 1e-3 * 0.1);
    CHECK(std::abs(ground["u"][2].get<double>()) <= 1e-15);
    CHECK(std::abs(ground["v"][2].get<double>()) <= 1e-15);
    // Every frame's coin centre lies over the square.
    const std::size_t markers = data["markers"].size(), centre = data["bodies"][0]["centre"].get<std::size_t>();
    for (std::size_t f = 0; f < data["times"].size(); ++f)
        for (int k = 0; k < 2; ++k)
            CHECK(std::abs(data["positions"][(f * markers + centre) * 3 + k].get<double>() -
                           ground["centre"][k].get<double>()) <= ground["half"].get<double>());

    // A ball falling freely: its lowest point drops, so there is no ground.
    const std::string falling = temporary_file("falling.lag", "parameters m g r\ncoordinates x z\n"
                                                              "body B ball(r) mass m at (x, 0, z)\n"
                                                              "gravity g along (0, 0, -1)\n"
                                                              "values m = 1, g = 9.81, r = 0.1\n"
                                                              "initial z = 1, x' = 0.5\nsimulate until 0.4\n");
    const std::string falling_html = temporary_file("falling.html", "");
    REQUIRE(run_cli("animate " + falling + " -o " + falling_html, "", 60).exit_code == 0);
    CHECK_FALSE(page_data(read_file(falling_html)).contains("ground"));
}
