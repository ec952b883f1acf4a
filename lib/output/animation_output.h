// SPDX-License-Identifier: GPL-2.0-or-later
/** @file animation_output.h
 *  An animation (numeric/animation.h) as one self-contained HTML page: the frames embedded
 *  as JSON, drawn on a canvas by a small script (discs sized by mass, rods, springs as coils,
 *  the pivot, trails, a clock and the energy drift; a free body by Poinsot's construction),
 *  with play and pause, a time slider, speed and view controls. No network: nothing is
 *  loaded from elsewhere. `#t=2.5` in the address opens the page paused at t = 2.5. Also
 *  the same pictures as an MP4 or GIF video. */
#pragma once

#include "numeric/animation.h"

#include <string>

namespace lagrange {

struct animation_view {
    double speed = 1;          ///< simulated time per second of playing
    double trail = 0;          ///< seconds of simulated time drawn behind each point (0: none)
    std::string view = "";     ///< "xy", "xz" or "3d" ("": xy for planar scenes, 3d otherwise)
    double fps = 30;           ///< videos: frames per second of the video
};

/// The page. The data sits in `<script id="lagrange-data" type="application/json">`; the
/// player is `window.lagrangePlayer` (time(), setTime(t), play(), pause(), playing()).
std::string animation_html(const animation_frames& frames, const animation_view& view, const std::string& title);

/// Throws computation_error saying what is missing when `path` (.mp4, .gif) cannot be
/// encoded here: ffmpeg not on $PATH (Debian package ffmpeg), or a build without cairo.
void check_video_encoder(const std::string& path);

/// MP4 (H.264) or GIF by ffmpeg (output/animation_video.cpp): one video frame per frame of
/// `frames`, at view.fps frames per second, drawn as the player draws them (trails, view).
/// Throws as check_video_encoder, and computation_error with ffmpeg's message when it fails.
void write_animation_video(const std::string& path, const animation_frames& frames, const animation_view& view);

/// Whether `view` is one of "", "xy", "xz", "3d".
bool known_animation_view(const std::string& view);

} // namespace lagrange
