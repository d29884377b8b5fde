// The page: connects to the server it came from, keeps the latest state of every topic, draws it,
// and (when the server allows control) drives the robot with the arrow keys, sends goals on a click
// and runs the simulation. window.jaria exposes the state for tests.
"use strict";

const $ = (id) => document.getElementById(id);
const world = { map: null, robots: new Map(), clock: null, frames: 0 };
const view = new WorldView($("view"));
let selected = null;
let control = new Set();
let dirty = true;
let fitted = false;
const errors = [];

const params = new URLSearchParams(location.search);
const token = params.get("token");
const wsUrl = `${location.protocol === "https:" ? "wss" : "ws"}://${location.host}/${token ? `?token=${encodeURIComponent(token)}` : ""}`;
$("wsurl").textContent = wsUrl;

function robot(name) {
  let r = world.robots.get(name);
  if (!r) {
    r = { name, sonar: { origins: [], echoes: [] }, particles: null, path: [], status: null };
    world.robots.set(name, r);
    const o = document.createElement("option");
    o.value = name; o.textContent = name;
    $("robot").appendChild(o);
    if (!selected) { selected = name; }
  }
  return r;
}

function onMessage(topic, m) {
  dirty = true;
  if (topic === "/map") {
    readMap(m);
    return;
  }
  if (topic === "/clock") {
    world.clock = m;
    world.frames++;
    return;
  }
  if (topic === "/robots") {
    for (const e of m.entities) {
      const name = e.id.replace(/^robot\//, "");
      const r = robot(name);
      if (e.lines.length && e.arrows.length) {
        const p = poseOf(e.arrows[0].pose);
        const t = (-p.th * Math.PI) / 180, c = Math.cos(t), s = Math.sin(t);
        r.local = e.lines[0].points.map((q) => {
          const dx = q.x * 1000 - p.x, dy = q.y * 1000 - p.y;
          return [dx * c - dy * s, dx * s + dy * c];
        });
      }
    }
    return;
  }
  if (topic === "/tf") return;
  const parts = topic.split("/");
  if (parts.length !== 3) return;
  const r = robot(parts[1]);
  switch (parts[2]) {
    case "true_pose": r.truePose = poseOf(m.pose); break;
    case "pose": r.pose = poseOf(m.pose); break;
    case "particles": r.particles = decodePoints(m); break;
    case "sonar": r.sonar = { echoes: decodePoints(m), origins: r.sonarOrigins || [] }; break;
    case "laser":
      r.laser = { origin: poseOf(m.pose), start: m.start_angle, inc: m.ranges.length > 1 ? (m.end_angle - m.start_angle) / (m.ranges.length - 1) : 0, ranges: m.ranges };
      break;
    case "path": r.path = m.poses.map((p) => poseOf(p)); break;
    case "status": r.status = m; break;
    default: break;
  }
  if (parts[2] === "sonar" && r.truePose) {
    // Beams start at the robot's centre here; the echoes are what matter.
    const o = new Float32Array(r.sonar.echoes.length);
    for (let i = 0; i < o.length; i += 2) { o[i] = r.truePose.x; o[i + 1] = r.truePose.y; }
    r.sonar.origins = o;
  }
}

function readMap(m) {
  const map = { walls: [], points: [], forbiddenLines: [], areas: [], goals: [] };
  for (const e of m.entities) {
    const flat = (line) => line.points.flatMap((q) => [q.x * 1000, q.y * 1000]);
    if (e.id === "walls" && e.lines.length) map.walls = flat(e.lines[0]);
    if (e.id === "points" && e.lines.length) {
      const p = flat(e.lines[0]), pts = [];
      for (let i = 0; i + 3 < p.length; i += 8) pts.push((p[i] + p[i + 2]) / 2, (p[i + 1] + p[i + 3]) / 2);
      map.points = pts;
    }
    if (e.id === "forbidden") {
      for (const l of e.lines) {
        if (l.type === 1) map.areas.push(flat(l)); else map.forbiddenLines = flat(l);
      }
    }
    if (e.id === "goals") {
      e.arrows.forEach((a, i) => {
        const p = poseOf(a.pose);
        map.goals.push({ name: e.texts[i] ? e.texts[i].text : "", x: p.x, y: p.y, th: p.th, heading: Math.abs(p.th) > 1e-6 });
      });
    }
  }
  const xs = [], ys = [];
  for (let i = 0; i + 1 < map.walls.length; i += 2) { xs.push(map.walls[i]); ys.push(map.walls[i + 1]); }
  map.bounds = xs.length
    ? { minX: Math.min(...xs), maxX: Math.max(...xs), minY: Math.min(...ys), maxY: Math.max(...ys) }
    : { minX: -5000, maxX: 5000, minY: -5000, maxY: 5000 };
  world.map = map;
  if (!fitted) { view.fit(map.bounds); fitted = true; }
}

function toast(text, warn) {
  const t = document.createElement("div");
  t.className = "toast" + (warn ? " warn" : "");
  t.textContent = text;
  $("toasts").appendChild(t);
  setTimeout(() => t.remove(), 5000);
}

const client = new FoxgloveClient(wsUrl, {
  onOpen: () => { $("conn").textContent = "connected"; $("conn").className = "pill ok"; },
  onClose: () => {
    $("conn").textContent = "disconnected"; $("conn").className = "pill bad";
    toast("The server closed the connection. Reload the page when it runs again.", true);
  },
  onServerInfo: (info) => {
    $("server").textContent = info.name;
    control = new Set((info.metadata["jaria.control"] || "").split(",").filter((s) => s));
    $("sim").hidden = !control.has("sim");
    $("drive").hidden = !control.has("drive");
    $("readonly").hidden = control.size > 0;
  },
  onStatus: (s) => toast(s.message, s.level > 0),
  onMessage,
});

// ---- drawing ----
function fmtPose(p) {
  return p ? `${(p.x / 1000).toFixed(2)}, ${(p.y / 1000).toFixed(2)} m, ${Math.round(p.th) + 0}°` : "–";
}

function fmtClock(c) {
  if (!c) return "--:--:--.-";
  const s = c.seconds, h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60);
  const t = `${String(h).padStart(2, "0")}:${String(m).padStart(2, "0")}:${(s % 60).toFixed(1).padStart(4, "0")}`;
  if (!c.simulated) return t;
  return `sim ${t}  ×${c.speedup === null ? "?" : +c.speedup.toFixed(2)}  ${c.paused ? "paused" : "running"}`;
}

function updatePanel() {
  const r = world.robots.get(selected);
  const s = r && r.status;
  $("s-mode").textContent = s ? s.mode : "–";
  $("s-pose").textContent = r ? fmtPose(r.pose || r.truePose) : "–";
  $("s-true").textContent = r && r.truePose ? fmtPose(r.truePose) : "–";
  $("s-vel").textContent = s ? `${s.vel.toFixed(0)} mm/s, ${s.rot_vel.toFixed(0)}°/s` : "–";
  $("s-batt").textContent = s && s.battery_volts !== null ? `${s.battery_volts.toFixed(1)} V` : "–";
  $("s-motors").textContent = s ? (s.motors_enabled ? "enabled" : "disabled") + (s.stalled ? ", STALLED" : "") : "–";
  $("s-loc").textContent = s && s.localization_score !== null ? `score ${s.localization_score.toFixed(2)}` : "–";
  $("clock").textContent = fmtClock(world.clock);
  if (world.clock && world.clock.simulated) $("run").textContent = world.clock.paused ? "Run" : "Pause";
  const bar = view.scaleBar();
  $("scalebar").style.width = `${bar.px.toFixed(0)}px`;
  $("scaletext").textContent = bar.mm >= 1000 ? `${bar.mm / 1000} m` : `${bar.mm} mm`;
}

function frame() {
  const r = world.robots.get(selected);
  if ($("follow").checked && r && (r.truePose || r.pose)) {
    const p = r.truePose || r.pose;
    view.cx = p.x; view.cy = p.y;
    dirty = true;
  }
  if (dirty) {
    view.draw(world, selected);
    updatePanel();
    dirty = false;
  }
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
window.addEventListener("resize", () => { dirty = true; });

// ---- legend ----
for (const [key, label, color] of LAYERS) {
  const li = document.createElement("li");
  li.innerHTML = `<input type="checkbox" checked id="layer-${key}"><span class="swatch"></span><label for="layer-${key}"></label>`;
  li.querySelector(".swatch").style.background = color;
  li.querySelector("label").textContent = label;
  li.querySelector("input").addEventListener("change", (e) => { view.layers[key] = e.target.checked; dirty = true; });
  $("legend").appendChild(li);
}
$("robot").addEventListener("change", (e) => { selected = e.target.value; dirty = true; });

// ---- mouse: pan, zoom, click for a goal ----
const canvas = $("view");
let drag = null;
canvas.addEventListener("mousedown", (e) => { drag = { x: e.offsetX, y: e.offsetY, moved: false }; });
window.addEventListener("mouseup", (e) => {
  if (drag && !drag.moved && e.target === canvas) clickAt(e.offsetX, e.offsetY);
  drag = null; canvas.classList.remove("dragging");
});
canvas.addEventListener("mousemove", (e) => {
  const [wx, wy] = view.toWorld(e.offsetX, e.offsetY);
  $("cursor").textContent = `${(wx / 1000).toFixed(2)}, ${(wy / 1000).toFixed(2)} m`;
  if (!drag) return;
  const dx = e.offsetX - drag.x, dy = e.offsetY - drag.y;
  if (!drag.moved && Math.hypot(dx, dy) < 4) return;
  drag.moved = true; canvas.classList.add("dragging");
  $("follow").checked = false;
  view.cx -= dx / view.scale; view.cy += dy / view.scale;
  drag.x = e.offsetX; drag.y = e.offsetY; dirty = true;
});
canvas.addEventListener("wheel", (e) => {
  e.preventDefault();
  view.zoomAt(e.offsetX, e.offsetY, Math.exp(-e.deltaY * 0.0015)); dirty = true;
}, { passive: false });

function clickAt(px, py) {
  canvas.focus();
  if (!control.has("goal")) return;
  const [x, y] = view.toWorld(px, py);
  view.pendingGoal = { x, y };
  client.publish("/goal", "foxglove.PoseInFrame", {
    frame_id: "map",
    pose: { position: { x: x / 1000, y: y / 1000, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 0 } },
  });
  setTimeout(() => { view.pendingGoal = null; dirty = true; }, 1500);
  dirty = true;
}

// ---- keys: drive while held ----
const held = new Set();
const KEYS = { ArrowUp: 1, ArrowDown: 1, ArrowLeft: 1, ArrowRight: 1 };
function twist() {
  const v = (held.has("ArrowUp") ? 400 : 0) - (held.has("ArrowDown") ? 300 : 0);
  const w = (held.has("ArrowLeft") ? 40 : 0) - (held.has("ArrowRight") ? 40 : 0);
  return { linear: { x: v / 1000, y: 0, z: 0 }, angular: { x: 0, y: 0, z: (w * Math.PI) / 180 } };
}
function sendDrive() { if (control.has("drive")) client.publish("/cmd_vel", "geometry_msgs/Twist", twist()); }
window.addEventListener("keydown", (e) => {
  if (e.target.tagName === "SELECT" || e.target.tagName === "INPUT") return;
  if (KEYS[e.key]) {
    e.preventDefault();
    if (!held.has(e.key)) { held.add(e.key); sendDrive(); }
  } else if (e.key === " ") {
    e.preventDefault(); held.clear(); sendDrive();
  } else if (e.key === "f" || e.key === "F") {
    $("follow").checked = !$("follow").checked; dirty = true;
  } else if (e.key === "0" && world.map) {
    $("follow").checked = false; view.fit(world.map.bounds); dirty = true;
  } else if (e.key === "+" || e.key === "=") {
    view.zoomAt(canvas.clientWidth / 2, canvas.clientHeight / 2, 1.25); dirty = true;
  } else if (e.key === "-") {
    view.zoomAt(canvas.clientWidth / 2, canvas.clientHeight / 2, 0.8); dirty = true;
  }
});
window.addEventListener("keyup", (e) => {
  if (KEYS[e.key] && held.delete(e.key)) sendDrive();
});
window.addEventListener("blur", () => { if (held.size) { held.clear(); sendDrive(); } });
setInterval(() => { if (held.size) sendDrive(); }, 200);

// ---- simulation ----
const sim = (command, value) => client.publish("/sim/control", "jaria.SimControl", { command, value });
$("run").addEventListener("click", () => sim(world.clock && world.clock.paused ? "run" : "pause"));
$("step").addEventListener("click", () => sim("step", 100));
$("speed").addEventListener("change", (e) => sim("speed", Number(e.target.value)));

window.addEventListener("error", (e) => errors.push(String(e.message)));

// For tests and the curious: the page's state and its mapping to the screen.
window.jaria = {
  world, view, errors,
  get selected() { return selected; },
  get control() { return [...control]; },
  screenOf(name) {
    const r = world.robots.get(name);
    const p = r && (r.truePose || r.pose);
    if (!p) return null;
    const [x, y] = view.toScreen(p.x, p.y);
    const b = canvas.getBoundingClientRect();
    return { x: x + b.left, y: y + b.top, truePose: r.truePose || null, pose: r.pose || null };
  },
  pageOf(x, y) {
    const [sx, sy] = view.toScreen(x, y);
    const b = canvas.getBoundingClientRect();
    return { x: sx + b.left, y: sy + b.top };
  },
};
