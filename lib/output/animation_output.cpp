// SPDX-License-Identifier: GPL-2.0-or-later
/** @file animation_output.cpp
 *  The animation's HTML page (see animation_output.h). The player is written here, in plain
 *  JavaScript on a 2-D canvas: it draws a few discs, lines, coils and bodies' wire outlines,
 *  which needs no library. */
#include "output/animation_output.h"

#include "core/number_text.h"
#include "core/errors.h"

#include <nlohmann/json.hpp>

#include <sstream>

namespace lagrange {

namespace {

/// Text safe inside HTML and inside a <script> element ("</" would end it).
std::string html_escape(const std::string& text)
{
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

const char* const player_script = R"JS(
(function () {
  "use strict";
  const D = JSON.parse(document.getElementById("lagrange-data").textContent);
  const canvas = document.getElementById("stage"), g = canvas.getContext("2d");
  const slider = document.getElementById("time"), button = document.getElementById("play");
  const speedBox = document.getElementById("speed"), viewBox = document.getElementById("view");
  const clock = document.getElementById("clock");
  const M = D.markers.length, F = D.times.length, T = D.times[F - 1], P = D.poinsot || null;
  const B = D.bodies.length;
  let t = 0, playing = false, last = null, speed = D.speed, view = D.view, yaw = 0.6, pitch = 0.35;
  slider.max = T; slider.step = D.step / 4;
  speedBox.value = String(speed);
  viewBox.value = view;
  // The position of marker m at time t, between the two frames around it (linear).
  function position(m, time) {
    const s = Math.min(Math.max(time / D.step, 0), F - 1), f = Math.min(Math.floor(s), F - 2), u = s - f;
    const a = (f * M + m) * 3, b = ((f + 1) * M + m) * 3, p = D.positions;
    if (F < 2) return [p[m * 3], p[m * 3 + 1], p[m * 3 + 2]];
    return [p[a] + u * (p[b] - p[a]), p[a + 1] + u * (p[b + 1] - p[a + 1]), p[a + 2] + u * (p[b + 2] - p[a + 2])];
  }
  // Frame data of n numbers per frame (a free body's rotation or contact point) at time t, linearly.
  function between(data, n, time) {
    const s = Math.min(Math.max(time / D.step, 0), F - 1), f = Math.min(Math.floor(s), Math.max(F - 2, 0)), u = F < 2 ? 0 : s - f;
    const out = [];
    for (let k = 0; k < n; ++k) out.push(data[f * n + k] + (F < 2 ? 0 : u * (data[(f + 1) * n + k] - data[f * n + k])));
    return out;
  }
  function turn(R, v) { return [R[0] * v[0] + R[1] * v[1] + R[2] * v[2], R[3] * v[0] + R[4] * v[1] + R[5] * v[2], R[6] * v[0] + R[7] * v[1] + R[8] * v[2]]; }
  // The bodies' rotations at time t: between the frames linearly, then made orthonormal again
  // (Gram–Schmidt on the columns), so that a fast spin between frames does not shrink the body.
  function rotationsAt(time) {
    const all = between(D.rotations, 9 * B, time), out = [];
    for (let b = 0; b < B; ++b) {
      const R = all.slice(9 * b, 9 * b + 9), c = [0, 1, 2].map(j => [R[j], R[3 + j], R[6 + j]]);
      const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      const unit = u => { const n = Math.sqrt(dot(u, u)); return u.map(x => x / n); };
      c[0] = unit(c[0]);
      c[1] = unit(c[1].map((x, k) => x - dot(c[1], c[0]) * c[0][k]));
      c[2] = [c[0][1] * c[1][2] - c[0][2] * c[1][1], c[0][2] * c[1][0] - c[0][0] * c[1][2], c[0][0] * c[1][1] - c[0][1] * c[1][0]];
      out.push([c[0][0], c[1][0], c[2][0], c[0][1], c[1][1], c[2][1], c[0][2], c[1][2], c[2][2]]);
    }
    return out;
  }
  // Body b's point r (in its axes, from its centre of mass) in the scene, for rotation R.
  function bodyPoint(b, R, time, r) {
    const c = position(D.bodies[b].centre, time), q = turn(R, r);
    return [c[0] + q[0], c[1] + q[1], c[2] + q[2]];
  }
  // Poinsot's construction: the plane's half width covers the ellipsoid and the herpolhode.
  let planeHalf = 0;
  if (P) {
    planeHalf = Math.max(...P.semi_axes);
    for (let f = 0; f < F; ++f) planeHalf = Math.max(planeHalf, Math.abs(P.contact[3 * f]), Math.abs(P.contact[3 * f + 1]));
    planeHalf *= 1.2;
  }
  function project(r) {
    if (view === "xz") return [r[0], r[2]];
    if (view === "3d") {
      const x = Math.cos(yaw) * r[0] - Math.sin(yaw) * r[1], y = Math.sin(yaw) * r[0] + Math.cos(yaw) * r[1];
      return [x, Math.cos(pitch) * r[2] - Math.sin(pitch) * y];
    }
    return [r[0], r[1]];
  }
  // The drawing's scale: every marker at every frame fits.
  let box;
  function fit() {
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    if (P) {
      const r = Math.max(...P.semi_axes);
      for (const s of [-1, 1]) for (const u of [-1, 1]) for (const z of [-r, r, -P.distance]) {
        const q = project(z === -P.distance ? [s * planeHalf, u * planeHalf, z] : [s * r, u * r, z]);
        lo = [Math.min(lo[0], q[0]), Math.min(lo[1], q[1])];
        hi = [Math.max(hi[0], q[0]), Math.max(hi[1], q[1])];
      }
    }
    const include = r => {
      const q = project(r);
      lo = [Math.min(lo[0], q[0]), Math.min(lo[1], q[1])];
      hi = [Math.max(hi[0], q[0]), Math.max(hi[1], q[1])];
    };
    for (let f = 0; f < F && !P; ++f) {
      for (let m = 0; m < M; ++m) if (D.markers[m].name) include(position(m, f * D.step));
      for (let b = 0; b < B; ++b) {
        const R = D.rotations.slice((f * B + b) * 9, (f * B + b) * 9 + 9);
        for (const line of D.bodies[b].outline)
          for (let k = 0; k < line.length; k += 3) include(bodyPoint(b, R, f * D.step, line.slice(k, k + 3)));
      }
    }
    const span = Math.max(hi[0] - lo[0], hi[1] - lo[1], 1e-9);
    box = {cx: (lo[0] + hi[0]) / 2, cy: (lo[1] + hi[1]) / 2, scale: 0.8 * Math.min(canvas.width, canvas.height) / span};
  }
  function screen(r) {
    const q = project(r);
    return [canvas.width / 2 + (q[0] - box.cx) * box.scale, canvas.height / 2 - (q[1] - box.cy) * box.scale];
  }
  const heaviest = Math.max(...D.markers.map(m => m.mass), 1e-300);
  function coil(a, b) {
    const dx = b[0] - a[0], dy = b[1] - a[1], L = Math.hypot(dx, dy), turns = 12;
    if (L === 0) return;
    const nx = -dy / L, ny = dx / L, w = 6;
    g.beginPath(); g.moveTo(a[0], a[1]);
    for (let k = 1; k < 2 * turns; ++k) {
      const u = (k + 0.5) / (2 * turns), side = k % 2 ? w : -w;
      g.lineTo(a[0] + dx * u + nx * side, a[1] + dy * u + ny * side);
    }
    g.lineTo(b[0], b[1]); g.stroke();
  }
  function polyline(points, colour, width) {
    g.strokeStyle = colour; g.lineWidth = width; g.beginPath();
    points.forEach((r, k) => { const q = screen(r); k ? g.lineTo(q[0], q[1]) : g.moveTo(q[0], q[1]); });
    g.stroke();
  }
  // The invariable plane (grid), the herpolhode on it, the inertia ellipsoid turned by R(t)
  // (meridians and parallels) with the polhode on it, the body axes, and ω through the contact.
  function drawPoinsot() {
    const R = between(P.rotation, 9, t), c = between(P.contact, 3, t), d = P.distance, h = planeHalf, a = P.semi_axes;
    for (let k = -4; k <= 4; ++k) {
      polyline([[k * h / 4, -h, -d], [k * h / 4, h, -d]], "#ddd", 1);
      polyline([[-h, k * h / 4, -d], [h, k * h / 4, -d]], "#ddd", 1);
    }
    const path = [];
    for (let f = 0; f < F && f * D.step <= t; ++f) path.push([P.contact[3 * f], P.contact[3 * f + 1], P.contact[3 * f + 2]]);
    path.push(c);
    polyline(path, "#1f77b4", 2);
    const surface = (u, v) => turn(R, [a[0] * Math.cos(u) * Math.cos(v), a[1] * Math.sin(u) * Math.cos(v), a[2] * Math.sin(v)]);
    for (let m = 0; m < 6; ++m) {
      const u = m * Math.PI / 6, line = [];
      for (let k = 0; k <= 48; ++k) line.push(surface(u, k * 2 * Math.PI / 48));
      polyline(line, "#aaa", 1);
    }
    for (let n = -2; n <= 2; ++n) {
      const v = n * Math.PI / 6, line = [];
      for (let k = 0; k <= 48; ++k) line.push(surface(k * 2 * Math.PI / 48, v));
      polyline(line, "#aaa", 1);
    }
    const polhode = [];
    for (let k = 0; k < P.polhode.length; k += 3) polhode.push(turn(R, P.polhode.slice(k, k + 3)));
    polyline(polhode, "#d62728", 2.5);
    ["#9467bd", "#8c564b", "#17becf"].forEach((colour, k) => {
      const e = [0, 0, 0]; e[k] = a[k];
      polyline([turn(R, e.map(x => -x)), turn(R, e)], colour, 1.5);
    });
    polyline([[0, 0, 0], c], "#ff7f0e", 2.5);
    const q = screen(c);
    g.fillStyle = "#ff7f0e"; g.beginPath(); g.arc(q[0], q[1], 5, 0, 2 * Math.PI); g.fill();
    g.fillStyle = "#333"; g.font = "13px sans-serif";
    g.fillText("inertia ellipsoid of " + P.body + ", polhode (red), herpolhode (blue), ω (orange)", 10, 18);
    return c;
  }
  // The state the page shows, for tests and links: time, playing, and where things are drawn.
  function publish(world) {
    canvas.dataset.time = String(t);
    canvas.dataset.playing = String(playing);
    canvas.dataset.world = JSON.stringify(world);
    canvas.dataset.screen = JSON.stringify(world.map(r => screen(r).map(x => Math.round(x * 100) / 100)));
  }
  function draw() {
    g.clearRect(0, 0, canvas.width, canvas.height);
    const f0 = Math.min(Math.round(t / D.step), F - 1);
    if (P) {
      const c = drawPoinsot();
      clock.textContent = "t = " + t.toFixed(2) + (D.drift.length ? "   energy drift " + D.drift[f0].toExponential(1) : "");
      slider.value = t;
      publish([c]);
      return;
    }
    const at = [];
    for (let m = 0; m < M; ++m) at.push(screen(position(m, t)));
    if (D.trail > 0) {
      g.strokeStyle = "rgba(31,119,180,0.35)"; g.lineWidth = 1.5;
      for (let m = 0; m < M; ++m) {
        if (!D.markers[m].point) continue;
        g.beginPath();
        const from = Math.max(0, t - D.trail);
        for (let s = from; s < t; s += D.step / 2) { const q = screen(position(m, s)); s === from ? g.moveTo(q[0], q[1]) : g.lineTo(q[0], q[1]); }
        g.lineTo(at[m][0], at[m][1]); g.stroke();
      }
    }
    // The ground (through the pivot, or under a body resting on it): a grid square normal to
    // gravity (a line seen edge-on).
    if (D.ground) {
      const G = D.ground, at = (a, b) => [0, 1, 2].map(k => G.centre[k] + G.half * (a * G.u[k] + b * G.v[k]));
      for (let k = -2; k <= 2; ++k) {
        polyline([at(k / 2, -1), at(k / 2, 1)], "#bbb", 1.5);
        polyline([at(-1, k / 2), at(1, k / 2)], "#bbb", 1.5);
      }
    }
    // The bodies: outlines turned to time t, and their axes 1, 2, 3 from the centre of mass.
    const turns = rotationsAt(t);
    for (let b = 0; b < B; ++b) {
      const body = D.bodies[b], R = turns[b];
      for (const line of body.outline) {
        const points = [];
        for (let k = 0; k < line.length; k += 3) points.push(bodyPoint(b, R, t, line.slice(k, k + 3)));
        polyline(points, "#2060c0", body.shape === "stick" ? 5 : 2);
      }
      ["#9467bd", "#8c564b", "#17becf"].forEach((colour, k) => {
        const e = [0, 0, 0]; e[k] = 0.75 * body.size;
        polyline([bodyPoint(b, R, t, [0, 0, 0]), bodyPoint(b, R, t, e)], colour, 1.5);
      });
    }
    g.strokeStyle = "#444"; g.lineWidth = 3;
    for (const r of D.rods) { g.beginPath(); g.moveTo(at[r[0]][0], at[r[0]][1]); g.lineTo(at[r[1]][0], at[r[1]][1]); g.stroke(); }
    g.strokeStyle = "#2ca02c"; g.lineWidth = 2;
    for (const s of D.springs) coil(at[s[0]], at[s[1]]);
    for (let m = 0; m < M; ++m) {
      const k = D.markers[m];
      if (k.name === "pivot" || k.name === "support") {
        g.fillStyle = k.name === "pivot" ? "#000" : "#7f7f7f"; // a moving support in grey
        g.fillRect(at[m][0] - 5, at[m][1] - 5, 10, 10);
      }
      if (!k.point) continue;
      g.fillStyle = "#d62728"; g.beginPath();
      g.arc(at[m][0], at[m][1], 6 + 14 * Math.cbrt(k.mass / heaviest), 0, 2 * Math.PI); g.fill();
    }
    const f = Math.min(Math.round(t / D.step), F - 1);
    clock.textContent = "t = " + t.toFixed(2) + (D.drift.length ? "   energy drift " + D.drift[f].toExponential(1) : "");
    slider.value = t;
    const world = [];
    for (let m = 0; m < M; ++m) world.push(position(m, t));
    canvas.dataset.rotations = JSON.stringify(turns);
    publish(world);
  }
  // Timers, not requestAnimationFrame: a headless browser (the test) runs timers on virtual
  // time but draws no animation frames.
  function frame() {
    if (!playing) return;
    const now = performance.now();
    if (last !== null) t += (now - last) / 1000 * speed;
    last = now;
    if (t >= T) { t = T; playing = false; button.textContent = "play"; }
    draw();
    if (playing) setTimeout(frame, 1000 / 60);
  }
  function play() { if (t >= T) t = 0; playing = true; last = null; button.textContent = "pause"; frame(); }
  function pause() { playing = false; button.textContent = "play"; canvas.dataset.playing = "false"; }
  function setTime(time) { t = Math.min(Math.max(Number(time), 0), T); draw(); }
  button.onclick = () => (playing ? pause() : play());
  slider.oninput = () => { pause(); setTime(slider.value); };
  speedBox.onchange = () => { speed = Number(speedBox.value); };
  viewBox.onchange = () => { view = viewBox.value; fit(); draw(); };
  let drag = null;
  canvas.onmousedown = e => { drag = [e.clientX, e.clientY]; };
  window.onmouseup = () => { drag = null; };
  canvas.onmousemove = e => {
    if (!drag || view !== "3d") return;
    yaw += (e.clientX - drag[0]) / 200; pitch += (e.clientY - drag[1]) / 200; drag = [e.clientX, e.clientY]; draw();
  };
  window.lagrangePlayer = { time: () => t, setTime, play, pause, playing: () => playing };
  fit();
  // #t=2.5: open paused at that time; otherwise play from the start.
  const wanted = /(?:^#|&)t=([0-9.eE+-]+)/.exec(location.hash);
  if (wanted && isFinite(Number(wanted[1]))) setTime(Number(wanted[1])); else { draw(); play(); }
})();
)JS";

} // namespace

bool known_animation_view(const std::string& view)
{
    return view.empty() || view == "xy" || view == "xz" || view == "3d";
}

std::string animation_html(const animation_frames& frames, const animation_view& view, const std::string& title)
{
    // The data, numbers as the shortest decimals that read back as the same double.
    std::ostringstream data;
    data << "{\"step\":" << shortest(frames.step) << ",\"speed\":" << shortest(view.speed)
         << ",\"trail\":" << shortest(view.trail) << ",\"view\":\""
         << (view.view.empty() ? (frames.dimensions == 2 ? "xy" : "3d") : view.view) << "\",\"markers\":[";
    for (std::size_t m = 0; m < frames.markers.size(); ++m)
        data << (m ? "," : "") << "{\"name\":" << nlohmann::json(frames.markers[m].name).dump()
             << ",\"mass\":" << shortest(frames.markers[m].mass)
             << ",\"point\":" << (frames.markers[m].point ? "true" : "false") << "}";
    data << "],\"rods\":[";
    for (std::size_t r = 0; r < frames.rods.size(); ++r)
        data << (r ? "," : "") << "[" << frames.rods[r].a << "," << frames.rods[r].b << "]";
    data << "],\"springs\":[";
    for (std::size_t s = 0; s < frames.springs.size(); ++s)
        data << (s ? "," : "") << "[" << frames.springs[s].a << "," << frames.springs[s].b << "]";
    data << "],\"bodies\":[";
    for (std::size_t b = 0; b < frames.bodies.size(); ++b) {
        const auto& body = frames.bodies[b];
        data << (b ? "," : "") << "{\"name\":" << nlohmann::json(body.name).dump()
             << ",\"shape\":" << nlohmann::json(body.shape).dump() << ",\"centre\":" << body.centre
             << ",\"size\":" << shortest(body.size) << ",\"outline\":[";
        for (std::size_t l = 0; l < body.outline.size(); ++l) {
            data << (l ? "," : "") << "[";
            bool first = true;
            for (const auto& r : body.outline[l])
                for (double x : r) {
                    data << (first ? "" : ",") << shortest(x);
                    first = false;
                }
            data << "]";
        }
        data << "]}";
    }
    data << "],\"rotations\":[";
    for (std::size_t k = 0; k < frames.rotations.size(); ++k)
        data << (k ? "," : "") << shortest(frames.rotations[k]);
    data << "]";
    if (frames.ground) {
        const auto& g = *frames.ground;
        data << ",\"ground\":{\"centre\":[" << shortest(g.centre[0]) << "," << shortest(g.centre[1]) << ","
             << shortest(g.centre[2]) << "],\"u\":[" << shortest(g.u[0]) << "," << shortest(g.u[1]) << ","
             << shortest(g.u[2]) << "],\"v\":[" << shortest(g.v[0]) << "," << shortest(g.v[1]) << ","
             << shortest(g.v[2]) << "],\"half\":" << shortest(g.half_width) << "}";
    }
    data << ",\"times\":[";
    for (std::size_t f = 0; f < frames.times.size(); ++f)
        data << (f ? "," : "") << shortest(frames.times[f]);
    data << "],\"positions\":[";
    for (std::size_t k = 0; k < frames.positions.size(); ++k)
        data << (k ? "," : "") << shortest(frames.positions[k]);
    data << "],\"drift\":[";
    for (std::size_t f = 0; f < frames.energy_drift.size(); ++f)
        data << (f ? "," : "") << shortest(frames.energy_drift[f]);
    data << "]";
    if (frames.poinsot) {
        const poinsot_motion& p = *frames.poinsot;
        auto triples = [&](const char* name, const auto& rows) {
            data << ",\"" << name << "\":[";
            bool first = true;
            for (const auto& row : rows)
                for (double x : row) {
                    data << (first ? "" : ",") << shortest(x);
                    first = false;
                }
            data << "]";
        };
        data << ",\"poinsot\":{\"body\":" << nlohmann::json(p.body).dump() << ",\"semi_axes\":[" << shortest(p.semi_axes[0])
             << "," << shortest(p.semi_axes[1]) << "," << shortest(p.semi_axes[2])
             << "],\"distance\":" << shortest(p.plane_distance);
        triples("rotation", p.rotation);
        triples("contact", p.contact);
        triples("polhode", p.polhode);
        data << "}";
    }
    data << ",\"method\":" << nlohmann::json(frames.method).dump() << "}";

    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(title)
        << "</title>\n<style>\nbody { font-family: sans-serif; margin: 1em; }\ncanvas { border: 1px solid #ccc; "
           "display: block; }\n#controls { margin-top: 0.5em; display: flex; gap: 0.7em; align-items: center; }\n"
           "#time { width: 420px; }\n#clock { font-family: monospace; }\n</style>\n</head>\n<body>\n<h3>"
        << html_escape(title) << "</h3>\n<canvas id=\"stage\" width=\"640\" height=\"560\"></canvas>\n"
        << "<div id=\"controls\"><button id=\"play\">play</button><input id=\"time\" type=\"range\" min=\"0\" "
           "value=\"0\"><label>speed <select id=\"speed\"><option>0.25</option><option>0.5</option><option>1</option>"
           "<option>2</option><option>4</option></select></label><label>view <select id=\"view\"><option>xy</option>"
           "<option>xz</option><option>3d</option></select></label><span id=\"clock\"></span></div>\n"
        << "<p>Drawn by lagrange from the simulation's dense output (" << html_escape(frames.method) << ", "
        << frames.steps << " steps). Link to a moment with #t=2.5.</p>\n"
        << "<script id=\"lagrange-data\" type=\"application/json\">" << data.str() << "</script>\n<script>"
        << player_script << "</script>\n</body>\n</html>\n";
    return out.str();
}

} // namespace lagrange
