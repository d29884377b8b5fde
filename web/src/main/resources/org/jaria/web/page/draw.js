// Draws the world on a canvas: the map (walls, points, forbidden places, goals), and for each
// robot its laser, sonar, particles, path, believed pose and true pose. Millimetres in, pixels out;
// y points up on the map and down on the screen.
"use strict";

const COLORS = {
  grid: "#e3e7ec", gridMajor: "#cfd5dc", wall: "#1d2733", point: "#4a5866",
  forbidden: "#d03030", goal: "#1f8f4a", laser: "#d6336c", sonar: "#e8890c",
  particles: "#2c6fbb", path: "#2c6fbb", robot: "#c0392b", believed: "#2c6fbb",
};

const LAYERS = [
  ["walls", "Walls", COLORS.wall], ["points", "Map points", COLORS.point],
  ["forbidden", "Forbidden areas", COLORS.forbidden], ["goals", "Goals", COLORS.goal],
  ["laser", "Laser", COLORS.laser], ["sonar", "Sonar", COLORS.sonar],
  ["particles", "Particles", COLORS.particles], ["path", "Planned path", COLORS.path],
  ["believed", "Believed pose", COLORS.believed], ["robot", "True pose", COLORS.robot],
];

class WorldView {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext("2d");
    this.scale = 0.05; // px per mm
    this.cx = 0; this.cy = 0; // map point at the canvas centre, mm
    this.layers = Object.fromEntries(LAYERS.map(([k]) => [k, true]));
    this.pendingGoal = null;
  }

  toScreen(x, y) {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    return [w / 2 + (x - this.cx) * this.scale, h / 2 - (y - this.cy) * this.scale];
  }

  toWorld(px, py) {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    return [this.cx + (px - w / 2) / this.scale, this.cy - (py - h / 2) / this.scale];
  }

  fit(bounds) {
    if (!bounds) return;
    const w = this.canvas.clientWidth || 800, h = this.canvas.clientHeight || 600;
    const bw = Math.max(bounds.maxX - bounds.minX, 1000), bh = Math.max(bounds.maxY - bounds.minY, 1000);
    this.scale = 0.92 * Math.min(w / bw, h / bh);
    this.cx = (bounds.minX + bounds.maxX) / 2;
    this.cy = (bounds.minY + bounds.maxY) / 2;
  }

  zoomAt(px, py, factor) {
    const [wx, wy] = this.toWorld(px, py);
    this.scale = Math.min(2, Math.max(0.002, this.scale * factor));
    const [nx, ny] = this.toWorld(px, py);
    this.cx += wx - nx; this.cy += wy - ny;
  }

  draw(world, selected) {
    const c = this.canvas, ctx = this.ctx;
    const dpr = window.devicePixelRatio || 1;
    const w = c.clientWidth, h = c.clientHeight;
    if (c.width !== Math.round(w * dpr) || c.height !== Math.round(h * dpr)) {
      c.width = Math.round(w * dpr); c.height = Math.round(h * dpr);
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#f8f9fb";
    ctx.fillRect(0, 0, w, h);
    this.grid(w, h);
    const m = world.map;
    if (m) {
      if (this.layers.forbidden) this.forbidden(m);
      if (this.layers.points) this.pointsLayer(m.points, COLORS.point, 1.6);
      if (this.layers.walls) this.segments(m.walls, COLORS.wall, 2);
      if (this.layers.goals) this.goals(m.goals);
    }
    for (const r of world.robots.values()) {
      this.robotSensors(r);
    }
    for (const r of world.robots.values()) {
      this.robotBody(r, r.name === selected);
    }
    if (this.pendingGoal) this.goalMarker(this.pendingGoal, COLORS.path);
  }

  grid(w, h) {
    const ctx = this.ctx;
    const step = this.scale > 0.08 ? 500 : this.scale > 0.015 ? 1000 : 5000;
    const [x0, y1] = this.toWorld(0, 0), [x1, y0] = this.toWorld(w, h);
    ctx.lineWidth = 1;
    for (let x = Math.floor(x0 / step) * step; x <= x1; x += step) {
      ctx.strokeStyle = x % (step * 5) === 0 ? COLORS.gridMajor : COLORS.grid;
      const [sx] = this.toScreen(x, 0);
      ctx.beginPath(); ctx.moveTo(Math.round(sx) + 0.5, 0); ctx.lineTo(Math.round(sx) + 0.5, h); ctx.stroke();
    }
    for (let y = Math.floor(y0 / step) * step; y <= y1; y += step) {
      ctx.strokeStyle = y % (step * 5) === 0 ? COLORS.gridMajor : COLORS.grid;
      const [, sy] = this.toScreen(0, y);
      ctx.beginPath(); ctx.moveTo(0, Math.round(sy) + 0.5); ctx.lineTo(w, Math.round(sy) + 0.5); ctx.stroke();
    }
  }

  segments(pts, color, width) {
    if (!pts || !pts.length) return;
    const ctx = this.ctx;
    ctx.strokeStyle = color; ctx.lineWidth = width; ctx.lineCap = "round";
    ctx.beginPath();
    for (let i = 0; i + 3 < pts.length; i += 4) {
      const [ax, ay] = this.toScreen(pts[i], pts[i + 1]);
      const [bx, by] = this.toScreen(pts[i + 2], pts[i + 3]);
      ctx.moveTo(ax, ay); ctx.lineTo(bx, by);
    }
    ctx.stroke();
  }

  pointsLayer(pts, color, size) {
    if (!pts || !pts.length) return;
    const ctx = this.ctx;
    ctx.fillStyle = color;
    for (let i = 0; i + 1 < pts.length; i += 2) {
      const [x, y] = this.toScreen(pts[i], pts[i + 1]);
      ctx.fillRect(x - size / 2, y - size / 2, size, size);
    }
  }

  forbidden(m) {
    const ctx = this.ctx;
    ctx.fillStyle = "rgba(208,48,48,0.14)"; ctx.strokeStyle = COLORS.forbidden; ctx.lineWidth = 1.5;
    for (const a of m.areas) {
      ctx.beginPath();
      for (let i = 0; i + 1 < a.length; i += 2) {
        const [x, y] = this.toScreen(a[i], a[i + 1]);
        if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      }
      ctx.closePath(); ctx.fill(); ctx.stroke();
    }
    this.segments(m.forbiddenLines, COLORS.forbidden, 3);
  }

  goals(goals) {
    const ctx = this.ctx;
    ctx.font = "11px system-ui, sans-serif";
    for (const g of goals) {
      const [x, y] = this.toScreen(g.x, g.y);
      ctx.strokeStyle = COLORS.goal; ctx.fillStyle = "rgba(31,143,74,0.15)"; ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.arc(x, y, 6, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      if (g.heading) {
        const t = (g.th * Math.PI) / 180;
        ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + 11 * Math.cos(t), y - 11 * Math.sin(t)); ctx.stroke();
      }
      ctx.fillStyle = COLORS.goal;
      ctx.fillText(g.name, x + 9, y - 7);
    }
  }

  goalMarker(g, color) {
    const ctx = this.ctx;
    const [x, y] = this.toScreen(g.x, g.y);
    ctx.strokeStyle = color; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.arc(x, y, 9, 0, 2 * Math.PI); ctx.stroke();
    ctx.beginPath(); ctx.moveTo(x - 13, y); ctx.lineTo(x + 13, y); ctx.moveTo(x, y - 13); ctx.lineTo(x, y + 13); ctx.stroke();
  }

  robotSensors(r) {
    const ctx = this.ctx;
    if (this.layers.particles && r.particles && r.particles.length) {
      ctx.fillStyle = "rgba(44,111,187,0.45)";
      for (let i = 0; i + 1 < r.particles.length; i += 2) {
        const [x, y] = this.toScreen(r.particles[i], r.particles[i + 1]);
        ctx.fillRect(x - 1, y - 1, 2, 2);
      }
    }
    if (this.layers.laser && r.laser) {
      const l = r.laser, o = l.origin;
      const [ox, oy] = this.toScreen(o.x, o.y);
      ctx.fillStyle = "rgba(214,51,108,0.07)";
      ctx.beginPath(); ctx.moveTo(ox, oy);
      const pts = [];
      for (let k = 0; k < l.ranges.length; k++) {
        const a = ((o.th * Math.PI) / 180) + l.start + k * l.inc;
        const d = l.ranges[k] * 1000;
        const p = this.toScreen(o.x + d * Math.cos(a), o.y + d * Math.sin(a));
        pts.push(p); ctx.lineTo(p[0], p[1]);
      }
      ctx.closePath(); ctx.fill();
      ctx.fillStyle = COLORS.laser;
      for (const [x, y] of pts) ctx.fillRect(x - 1.2, y - 1.2, 2.4, 2.4);
    }
    if (this.layers.sonar && r.sonar) {
      const s = r.sonar;
      ctx.strokeStyle = "rgba(232,137,12,0.35)"; ctx.lineWidth = 1;
      ctx.beginPath();
      for (let i = 0; i + 1 < s.echoes.length; i += 2) {
        const [ax, ay] = this.toScreen(s.origins[i], s.origins[i + 1]);
        const [bx, by] = this.toScreen(s.echoes[i], s.echoes[i + 1]);
        ctx.moveTo(ax, ay); ctx.lineTo(bx, by);
      }
      ctx.stroke();
      ctx.fillStyle = COLORS.sonar;
      for (let i = 0; i + 1 < s.echoes.length; i += 2) {
        const [x, y] = this.toScreen(s.echoes[i], s.echoes[i + 1]);
        ctx.beginPath(); ctx.arc(x, y, 2.6, 0, 2 * Math.PI); ctx.fill();
      }
    }
    if (this.layers.path && r.path && r.path.length > 1) {
      ctx.strokeStyle = COLORS.path; ctx.lineWidth = 2.5; ctx.setLineDash([8, 5]);
      ctx.beginPath();
      r.path.forEach((p, i) => {
        const [x, y] = this.toScreen(p.x, p.y);
        if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      });
      ctx.stroke(); ctx.setLineDash([]);
      this.goalMarker(r.path[r.path.length - 1], COLORS.path);
    }
  }

  robotBody(r, selected) {
    const ctx = this.ctx;
    if (this.layers.believed && r.pose && r.truePose) {
      this.outline(r, r.pose, null, COLORS.believed, 1.5, [5, 3]);
    }
    const shown = r.truePose || r.pose;
    if (!shown || !this.layers.robot) return;
    this.outline(r, shown, "rgba(192,57,43,0.82)", "#7b1d14", selected ? 2.2 : 1.5, []);
    const [x, y] = this.toScreen(shown.x, shown.y);
    ctx.fillStyle = COLORS.wall; ctx.font = "600 11px system-ui, sans-serif";
    ctx.fillText(r.name, x + 14, y - 14);
  }

  /** The robot's outline at pose p (its footprint moved from where it was drawn to p). */
  outline(r, p, fill, stroke, width, dash) {
    const ctx = this.ctx;
    const f = r.local || [[250, -190], [250, 190], [-250, 190], [-250, -190]];
    const t = (p.th * Math.PI) / 180, c = Math.cos(t), s = Math.sin(t);
    ctx.beginPath();
    f.forEach(([lx, ly], i) => {
      const [x, y] = this.toScreen(p.x + lx * c - ly * s, p.y + lx * s + ly * c);
      if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
    });
    ctx.closePath();
    if (fill) { ctx.fillStyle = fill; ctx.fill(); }
    ctx.setLineDash(dash); ctx.strokeStyle = stroke; ctx.lineWidth = width; ctx.stroke(); ctx.setLineDash([]);
    // heading: a line from the centre to the front
    const front = Math.max(...f.map(([lx]) => lx));
    const [ax, ay] = this.toScreen(p.x, p.y);
    const [bx, by] = this.toScreen(p.x + front * c, p.y + front * s);
    ctx.strokeStyle = fill ? "#ffffff" : stroke; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(ax, ay); ctx.lineTo(bx, by); ctx.stroke();
  }

  /** A scale bar length (mm) near 100 px. */
  scaleBar() {
    const target = 100 / this.scale;
    const steps = [100, 200, 500, 1000, 2000, 5000, 10000, 20000, 50000];
    const mm = steps.find((v) => v >= target * 0.6) || 50000;
    return { mm, px: mm * this.scale };
  }
}
