// SPDX-License-Identifier: GPL-2.0-or-later
/** @file animation_video.cpp
 *  MP4 and GIF of an animation (see animation_output.h): each frame drawn by cairo — the same
 *  picture as the HTML player's canvas: discs, bodies by shape with their axes, rods, coils,
 *  the pivot and moving supports, trails, Poinsot's
 *  construction, a clock and the energy drift — and its pixels piped to ffmpeg, which runs as
 *  every external program does (system/external.h: no shell, its own process group, a timeout). */
#include "output/animation_output.h"

#include "core/errors.h"
#include "system/external.h"
#include "system/files.h"

#ifdef LAGRANGE_HAVE_CAIRO
#include <cairo.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>

namespace lagrange {

namespace {

using point3 = std::array<double, 3>;

bool ends_with(const std::string& text, const std::string& suffix)
{
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

#ifdef LAGRANGE_HAVE_CAIRO

constexpr int width = 640, height = 480;

/// The picture's projection (as the player's: xy, xz, or 3d turned by a fixed yaw and pitch)
/// and scale, fitted so that everything drawn at every frame is inside.
class canvas_view {
public:
    canvas_view(const std::string& view) : view_(view) {}
    std::array<double, 2> project(const point3& r) const
    {
        if (view_ == "xz")
            return {r[0], r[2]};
        if (view_ == "3d") {
            const double yaw = 0.6, pitch = 0.35;
            const double x = std::cos(yaw) * r[0] - std::sin(yaw) * r[1], y = std::sin(yaw) * r[0] + std::cos(yaw) * r[1];
            return {x, std::cos(pitch) * r[2] - std::sin(pitch) * y};
        }
        return {r[0], r[1]};
    }
    void include(const point3& r)
    {
        const auto q = project(r);
        for (int k = 0; k < 2; ++k) {
            lo_[k] = std::min(lo_[k], q[k]);
            hi_[k] = std::max(hi_[k], q[k]);
        }
    }
    void finish()
    {
        const double span = std::max({hi_[0] - lo_[0], hi_[1] - lo_[1], 1e-9});
        scale_ = 0.8 * std::min(width, height) / span;
        centre_ = {(lo_[0] + hi_[0]) / 2, (lo_[1] + hi_[1]) / 2};
    }
    std::array<double, 2> screen(const point3& r) const
    {
        const auto q = project(r);
        return {width / 2.0 + (q[0] - centre_[0]) * scale_, height / 2.0 - (q[1] - centre_[1]) * scale_};
    }

private:
    std::string view_;
    double lo_[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double hi_[2] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    std::array<double, 2> centre_{};
    double scale_ = 1;
};

/// ffmpeg's name of cairo's RGB24 layout in memory (a native-endian 32-bit xRGB word).
const char* cairo_pixel_format()
{
    const std::uint32_t word = 1;
    return *reinterpret_cast<const unsigned char*>(&word) == 1 ? "bgr0" : "0rgb";
}

void colour(cairo_t* g, unsigned rgb, double alpha = 1)
{
    cairo_set_source_rgba(g, ((rgb >> 16) & 255) / 255.0, ((rgb >> 8) & 255) / 255.0, (rgb & 255) / 255.0, alpha);
}

void polyline(cairo_t* g, const canvas_view& v, const std::vector<point3>& points, unsigned rgb, double line)
{
    if (points.size() < 2)
        return;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const auto q = v.screen(points[k]);
        k ? cairo_line_to(g, q[0], q[1]) : cairo_move_to(g, q[0], q[1]);
    }
    colour(g, rgb);
    cairo_set_line_width(g, line);
    cairo_stroke(g);
}

point3 turn(const std::array<double, 9>& R, const point3& v)
{
    return {R[0] * v[0] + R[1] * v[1] + R[2] * v[2], R[3] * v[0] + R[4] * v[1] + R[5] * v[2],
            R[6] * v[0] + R[7] * v[1] + R[8] * v[2]};
}

/// The half width of the invariable plane's square: the ellipsoid and the herpolhode fit.
double plane_half_width(const poinsot_motion& m)
{
    double half = std::max({m.semi_axes[0], m.semi_axes[1], m.semi_axes[2]});
    for (const point3& c : m.contact)
        half = std::max({half, std::abs(c[0]), std::abs(c[1])});
    return 1.2 * half;
}

void draw_poinsot(cairo_t* g, const canvas_view& v, const poinsot_motion& m, std::size_t f)
{
    const double d = m.plane_distance, h = plane_half_width(m);
    const auto& R = m.rotation[f];
    const auto& a = m.semi_axes;
    for (int k = -4; k <= 4; ++k) {
        polyline(g, v, {{k * h / 4, -h, -d}, {k * h / 4, h, -d}}, 0xdddddd, 1);
        polyline(g, v, {{-h, k * h / 4, -d}, {h, k * h / 4, -d}}, 0xdddddd, 1);
    }
    polyline(g, v, std::vector<point3>(m.contact.begin(), m.contact.begin() + static_cast<long>(f + 1)), 0x1f77b4, 2);
    auto surface = [&](double u, double w) {
        return turn(R, {a[0] * std::cos(u) * std::cos(w), a[1] * std::sin(u) * std::cos(w), a[2] * std::sin(w)});
    };
    for (int n = 0; n < 6; ++n) {
        std::vector<point3> meridian, parallel;
        for (int k = 0; k <= 48; ++k) {
            meridian.push_back(surface(n * M_PI / 6, k * 2 * M_PI / 48));
            if (n < 5)
                parallel.push_back(surface(k * 2 * M_PI / 48, (n - 2) * M_PI / 6));
        }
        polyline(g, v, meridian, 0xaaaaaa, 1);
        polyline(g, v, parallel, 0xaaaaaa, 1);
    }
    std::vector<point3> polhode;
    for (const point3& b : m.polhode)
        polhode.push_back(turn(R, b));
    polyline(g, v, polhode, 0xd62728, 2.5);
    const point3& c = m.contact[f];
    polyline(g, v, {{0, 0, 0}, c}, 0xff7f0e, 2.5);
    const auto q = v.screen(c);
    colour(g, 0xff7f0e);
    cairo_arc(g, q[0], q[1], 5, 0, 2 * M_PI);
    cairo_fill(g);
}

void coil(cairo_t* g, std::array<double, 2> a, std::array<double, 2> b)
{
    const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
    if (length == 0)
        return;
    const int turns = 12;
    const double nx = -dy / length, ny = dx / length, w = 6;
    cairo_move_to(g, a[0], a[1]);
    for (int k = 1; k < 2 * turns; ++k) {
        const double u = (k + 0.5) / (2 * turns), side = k % 2 ? w : -w;
        cairo_line_to(g, a[0] + dx * u + nx * side, a[1] + dy * u + ny * side);
    }
    cairo_line_to(g, b[0], b[1]);
    colour(g, 0x2ca02c);
    cairo_set_line_width(g, 2);
    cairo_stroke(g);
}

point3 marker_at(const animation_frames& frames, std::size_t f, std::size_t m)
{
    const double* p = frames.at(f, m);
    return {p[0], p[1], p[2]};
}

/// Body b's point r (in its axes, from its centre of mass) in the scene at frame f.
point3 body_point(const animation_frames& frames, std::size_t f, std::size_t b, const point3& r)
{
    const point3 c = marker_at(frames, f, frames.bodies[b].centre);
    std::array<double, 9> R;
    std::copy(frames.rotation(f, b), frames.rotation(f, b) + 9, R.begin());
    const point3 turned = turn(R, r);
    return {c[0] + turned[0], c[1] + turned[1], c[2] + turned[2]};
}

/// The bodies: their outlines turned to frame f (a stick thick, others thin), and their body
/// axes from the centre of mass (1, 2, 3: purple, brown, cyan, as Poinsot's construction's).
void draw_bodies(cairo_t* g, const canvas_view& v, const animation_frames& frames, std::size_t f)
{
    for (std::size_t b = 0; b < frames.bodies.size(); ++b) {
        const auto& body = frames.bodies[b];
        for (const auto& line : body.outline) {
            std::vector<point3> turned;
            for (const point3& r : line)
                turned.push_back(body_point(frames, f, b, r));
            polyline(g, v, turned, 0x2060c0, body.shape == "stick" ? 5 : 2);
        }
        const unsigned axis_colours[3] = {0x9467bd, 0x8c564b, 0x17becf};
        for (int k = 0; k < 3; ++k) {
            point3 e{0, 0, 0};
            e[static_cast<std::size_t>(k)] = 0.75 * body.size;
            polyline(g, v, {body_point(frames, f, b, {0, 0, 0}), body_point(frames, f, b, e)}, axis_colours[k], 1.5);
        }
    }
}

void draw_points(cairo_t* g, const canvas_view& v, const animation_frames& frames, std::size_t f, std::size_t trail)
{
    const std::size_t markers = frames.markers.size();
    double heaviest = 1e-300;
    for (const auto& k : frames.markers)
        heaviest = std::max(heaviest, k.mass);
    for (std::size_t m = 0; m < markers && trail > 0; ++m) {
        if (!frames.markers[m].point)
            continue;
        std::vector<point3> path;
        for (std::size_t s = f >= trail ? f - trail : 0; s <= f; ++s)
            path.push_back(marker_at(frames, s, m));
        polyline(g, v, path, 0x8fbbd9, 1.5);
    }
    if (frames.ground) {
        // The ground (through the pivot, or under a body resting on it): a grid square normal to
        // gravity (a line when seen edge-on).
        const auto& s = *frames.ground;
        for (int k = -2; k <= 2; ++k) {
            auto at = [&](double a, double b) {
                return point3{s.centre[0] + s.half_width * (a * s.u[0] + b * s.v[0]),
                              s.centre[1] + s.half_width * (a * s.u[1] + b * s.v[1]),
                              s.centre[2] + s.half_width * (a * s.u[2] + b * s.v[2])};
            };
            polyline(g, v, {at(k / 2.0, -1), at(k / 2.0, 1)}, 0xbbbbbb, 1.5);
            polyline(g, v, {at(-1, k / 2.0), at(1, k / 2.0)}, 0xbbbbbb, 1.5);
        }
    }
    draw_bodies(g, v, frames, f);
    for (const auto& rod : frames.rods)
        polyline(g, v, {marker_at(frames, f, rod.a), marker_at(frames, f, rod.b)}, 0x444444, 3);
    for (const auto& spring : frames.springs)
        coil(g, v.screen(marker_at(frames, f, spring.a)), v.screen(marker_at(frames, f, spring.b)));
    for (std::size_t m = 0; m < markers; ++m) {
        const auto& k = frames.markers[m];
        const auto q = v.screen(marker_at(frames, f, m));
        if (k.name == "pivot" || k.name == "support") {
            colour(g, k.name == "pivot" ? 0x000000 : 0x7f7f7f); // a moving support in grey
            cairo_rectangle(g, q[0] - 5, q[1] - 5, 10, 10);
            cairo_fill(g);
        }
        if (!k.point)
            continue;
        colour(g, 0xd62728);
        cairo_arc(g, q[0], q[1], 6 + 14 * std::cbrt(k.mass / heaviest), 0, 2 * M_PI);
        cairo_fill(g);
    }
}

/// Draws every frame and hands its pixels (BGRx, `width` × `height`) to `write`, until it
/// returns false (ffmpeg has stopped reading).
void draw_frames(const animation_frames& frames, const animation_view& view,
                 const std::function<bool(const char*, std::size_t)>& write)
{
    canvas_view v(view.view.empty() ? (frames.dimensions == 2 ? "xy" : "3d") : view.view);
    const std::size_t count = frames.times.size();
    if (frames.poinsot) {
        const poinsot_motion& m = *frames.poinsot;
        const double r = std::max({m.semi_axes[0], m.semi_axes[1], m.semi_axes[2]}), h = plane_half_width(m);
        for (double s : {-1.0, 1.0})
            for (double u : {-1.0, 1.0})
                for (double z : {-r, r}) {
                    v.include({s * r, u * r, z});
                    v.include({s * h, u * h, -m.plane_distance});
                }
    } else {
        for (std::size_t f = 0; f < count; ++f) {
            for (std::size_t k = 0; k < frames.markers.size(); ++k)
                if (!frames.markers[k].name.empty())
                    v.include(marker_at(frames, f, k));
            for (std::size_t b = 0; b < frames.bodies.size(); ++b)
                for (const auto& line : frames.bodies[b].outline)
                    for (const point3& r : line)
                        v.include(body_point(frames, f, b, r));
        }
    }
    v.finish();
    const std::size_t trail = static_cast<std::size_t>(std::lround(view.trail / frames.step));
    std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), cairo_surface_destroy);
    std::unique_ptr<cairo_t, void (*)(cairo_t*)> context(cairo_create(surface.get()), cairo_destroy);
    cairo_t* g = context.get();
    cairo_set_line_join(g, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(g, CAIRO_LINE_CAP_ROUND);
    cairo_select_font_face(g, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(g, 15);
    for (std::size_t f = 0; f < count; ++f) {
        colour(g, 0xffffff);
        cairo_paint(g);
        if (frames.poinsot)
            draw_poinsot(g, v, *frames.poinsot, f);
        else
            draw_points(g, v, frames, f, trail);
        char clock[96];
        if (f < frames.energy_drift.size())
            std::snprintf(clock, sizeof clock, "t = %.2f   energy drift %.1e", frames.times[f], frames.energy_drift[f]);
        else
            std::snprintf(clock, sizeof clock, "t = %.2f", frames.times[f]);
        colour(g, 0x333333);
        cairo_move_to(g, 12, height - 14);
        cairo_show_text(g, clock);
        cairo_surface_flush(surface.get());
        const auto* pixels = reinterpret_cast<const char*>(cairo_image_surface_get_data(surface.get()));
        const int stride = cairo_image_surface_get_stride(surface.get());
        for (int row = 0; row < height; ++row)
            if (!write(pixels + static_cast<std::ptrdiff_t>(row) * stride, static_cast<std::size_t>(width) * 4))
                return;
    }
}

#endif

} // namespace

void check_video_encoder(const std::string& path)
{
    if (!program_available("ffmpeg"))
        throw computation_error("ffmpeg is not installed (Debian package ffmpeg), so `" + path +
                                "` cannot be encoded: install it, or write the self-contained player with -o FILE.html");
#ifndef LAGRANGE_HAVE_CAIRO
    throw computation_error("this build draws no video frames (it was built without cairo, Debian package "
                            "libcairo2-dev), so `" + path + "` cannot be written: write the self-contained player "
                            "with -o FILE.html");
#endif
}

void write_animation_video(const std::string& path, [[maybe_unused]] const animation_frames& frames,
                           const animation_view& view)
{
    check_video_encoder(path);
    [[maybe_unused]] const bool gif = ends_with(path, ".gif");
    if (!gif && !ends_with(path, ".mp4"))
        throw std::invalid_argument("a video is written as .mp4 or .gif, not `" + path + "`");
    if (!(view.fps > 0) || !std::isfinite(view.fps))
        throw std::invalid_argument("the video's frame rate must be positive");
#ifdef LAGRANGE_HAVE_CAIRO
    private_directory folder("lagrange-video");
    char rate[32], size[32];
    std::snprintf(rate, sizeof rate, "%.17g", view.fps);
    std::snprintf(size, sizeof size, "%dx%d", width, height);
    const std::string output = gif ? "video.gif" : "video.mp4";
    // Raw frames on standard input: cairo's RGB24 is BGRx in memory on little-endian machines.
    std::vector<std::string> arguments{"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                                       "-pixel_format", cairo_pixel_format(), "-video_size", size, "-framerate", rate,
                                       "-i", "-"};
    if (gif)
        // A palette per frame: one for the whole video would hold every frame in memory first.
        arguments.insert(arguments.end(), {"-filter_complex", "[0:v]split[a][b];[a]palettegen=stats_mode=single[p];"
                                                              "[b][p]paletteuse=new=1:dither=none"});
    else
        arguments.insert(arguments.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20"});
    arguments.push_back(output);
    const program_result run = run_program_fed(
        arguments, folder.path(), "ffmpeg.log", [&](const auto& write) { draw_frames(frames, view, write); }, 600);
    if (run.exit_code != 0)
        throw computation_error("ffmpeg could not encode `" + path + "`" +
                                (run.timed_out ? std::string(" (it took longer than 600 s)") : std::string()) + ": " +
                                folder.read("ffmpeg.log"));
    write_output(path, folder.read(output));
#endif
}

} // namespace lagrange
