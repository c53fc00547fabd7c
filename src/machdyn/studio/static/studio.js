// machdyn studio: the page edits the problem file's quantities, the server judges and computes, the page draws.
// Nothing is solved here: positions, forces and the summary come from the server (the run's own numbers).
(function () {
  "use strict";
  const token = new URLSearchParams(location.search).get("token") || "";
  const headers = { "Content-Type": "application/json", "X-Studio-Token": token };
  const $ = (id) => document.getElementById(id);
  const SVG = "http://www.w3.org/2000/svg";
  const W = 640, H = 420;
  let fields = [], values = {}, history = [], future = [], last = null, frame = 0, playing = false;
  let busy = false, again = false, view = null, drag = null;
  // the time of the first edit not yet drawn (the input event's own time stamp), and the edits measured so far:
  // the page's latency is from that event to the frame after the redrawn view and plots
  let editStart = null, edits = 0;

  function edited(e) {
    if (editStart === null) editStart = e && e.timeStamp ? e.timeStamp : performance.now();
    recompute();
  }

  async function api(path, body) {
    const response = await fetch(path, body === undefined ? { headers } :
      { method: "POST", headers, body: JSON.stringify(body) });
    return response.json();
  }

  function el(tag, attrs, parent) {
    const node = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
    if (parent) parent.appendChild(node);
    return node;
  }

  function fmt(v) {
    if (v === null || v === undefined) return "–";
    if (Array.isArray(v)) return v.map(fmt).join(", ");
    if (typeof v !== "number") return String(v);
    if (v === 0) return "0";
    const a = Math.abs(v);
    return (a >= 1e5 || a < 1e-3) ? v.toExponential(3) : String(Number(v.toPrecision(4)));
  }

  // ------------------------------------------------------------------ fields, history
  function buildFields(editable) {
    const body = $("fields").tBodies[0];
    body.textContent = "";
    for (const f of fields) {
      const row = body.insertRow();
      row.dataset.key = f.key;
      row.insertCell().textContent = f.key;
      row.cells[0].className = "key";
      const input = document.createElement("input");
      input.type = "number"; input.step = "any"; input.value = f.number; input.name = f.key;
      input.disabled = !editable;
      input.setAttribute("aria-label", f.key);
      input.addEventListener("change", (e) => {
        if (values[f.key] === input.value) return;  // one edit, however many change events
        record(); values[f.key] = input.value; edited(e);
      });
      row.insertCell().appendChild(input);
      const range = bounds(f);
      if (range && editable) {  // a slider over a sensible span around the file's value
        const slide = document.createElement("input");
        slide.type = "range"; slide.className = "nudge"; slide.min = range[0]; slide.max = range[1];
        slide.step = range[2]; slide.value = f.number;  // the file's value sits on the slider's grid
        slide.setAttribute("aria-label", f.key + " slider");
        let sliding = false;
        slide.addEventListener("input", (e) => {
          if (!sliding) { record(); sliding = true; }
          input.value = values[f.key] = String(Number(Number(slide.value).toPrecision(5)));
          edited(e);
        });
        slide.addEventListener("change", () => { sliding = false; });
        input.addEventListener("change", () => { slide.value = input.value; });
        row.cells[1].appendChild(slide);
      }
      row.insertCell().textContent = f.unit;
      const msg = document.createElement("div");
      msg.className = "error";
      row.cells[1].appendChild(msg);
      values[f.key] = f.number;
    }
  }

  // from half to twice the file's value (its sign kept) in steps of 0.5 %, a whole turn for an angle at zero;
  // none for counts
  function bounds(f) {
    const v = Number(f.number);
    if (f.integer || !f.unit || !Number.isFinite(v)) return null;
    if (v === 0) return /^(deg|degree|degrees|°)$/.test(f.unit) ? [-180, 180, 1] : null;
    return v > 0 ? [v / 2, 2 * v, v / 200] : [2 * v, v / 2, -v / 200];
  }

  function record() {
    history.push(Object.assign({}, values));
    future = [];
    buttons();
  }

  function buttons() { $("undo").disabled = !history.length; $("redo").disabled = !future.length; }

  function restore(snapshot) {
    values = Object.assign({}, snapshot);
    for (const row of $("fields").tBodies[0].rows) {
      for (const input of row.querySelectorAll("input")) input.value = values[row.dataset.key];
    }
    buttons();
    edited();
  }

  $("undo").addEventListener("click", () => { if (history.length) { future.push(values); restore(history.pop()); } });
  $("redo").addEventListener("click", () => { if (future.length) { history.push(values); restore(future.pop()); } });

  // ------------------------------------------------------------------ the server
  let wantFull = false;  // Full run pressed while a request ran: it follows that request
  async function recompute(full) {
    if (busy) { again = true; wantFull = wantFull || Boolean(full); return; }  // one at a time; the latest follows
    busy = true;
    document.body.dataset.busy = "1";
    const started = full ? null : editStart;  // an edit made while this request runs is measured with the next
    if (!full) editStart = null;
    try {
      const answer = await api(full ? "/api/full" : "/api/evaluate", { values });
      show(answer);
      if (started !== null) measured(started);
    } catch (e) {
      $("status").textContent = "the studio's server does not answer";
    }
    busy = false;
    if (again) { again = false; const f = wantFull; wantFull = false; recompute(f); }
    else document.body.dataset.busy = "0";
  }

  // the frame after the redraw has been laid out: the edit's latency as the user sees it
  function measured(started) {
    requestAnimationFrame(() => {
      const ms = performance.now() - started;
      performance.measure("studio edit", { start: started, duration: ms });
      edits += 1;
      $("latency").textContent = `edit → redrawn in ${ms.toFixed(0)} ms`;
      $("latency").dataset.ms = ms.toFixed(2);
      document.body.dataset.edits = String(edits);
    });
  }

  function show(answer) {
    for (const row of $("fields").tBodies[0].rows) { row.classList.remove("bad"); row.querySelector(".error").textContent = ""; }
    if (!answer.ok) {
      $("stale").hidden = last === null;
      $("check").textContent = answer.message || "";
      const loose = [];
      for (const p of answer.problems || []) {
        const row = [...$("fields").tBodies[0].rows].find((r) => r.dataset.key === p.path ||
          r.dataset.key.startsWith(p.path + ".") || r.dataset.key.startsWith(p.path + "["));
        if (row && p.path) { row.classList.add("bad"); row.querySelector(".error").textContent = p.message; }
        else loose.push(p);
      }
      $("status").textContent = "invalid" + (answer.compute_ms !== undefined ? ` (checked in ${answer.compute_ms} ms)` : "");
      if (last === null) { $("stale").hidden = false; }
      document.body.dataset.state = "invalid";
      return;
    }
    last = answer;
    $("stale").hidden = true;
    $("check").textContent = "";
    $("status").textContent = `computed in ${answer.compute_ms} ms`;
    $("title").textContent = answer.title || "machdyn studio";
    const head = answer.headline;
    $("peaklabel").textContent = head ? head.label : "Peak driving torque";
    $("peak").textContent = head && head.value !== null ? `${fmt(head.value)} ${head.unit}` : "–";
    $("warnings").textContent = "";
    for (const w of [...answer.warnings, ...answer.failed_checks.map((c) => "design check failed: " + c)]) {
      const p = document.createElement("p"); p.className = "warning"; p.textContent = w; $("warnings").appendChild(p);
    }
    const body = $("summary").tBodies[0];
    body.textContent = "";
    $("deferred").hidden = !(answer.deferred && answer.deferred.length && !answer.full);
    $("deferredtables").textContent = (answer.deferred || []).join(", ");
    $("fullmark").hidden = !(answer.deferred && answer.deferred.length && answer.full);
    for (const r of answer.summary) {
      const row = body.insertRow();
      if (r.live) row.className = "live";
      row.insertCell().textContent = r.label + (r.live ? " (live estimate)" : "");
      row.insertCell().textContent = fmt(r.value);
      row.cells[1].className = "value";
      row.insertCell().textContent = r.unit;
    }
    if (answer.scene) {
      const s = answer.scene;
      $("slider").max = s.angles.length - 1;
      frame = Math.min(frame, s.angles.length - 1);
      if (!view || !drag && outside(s)) view = fit(s);
    } else if (answer.cam) {
      const c = answer.cam;
      $("slider").max = c.angles.length - 1;
      frame = Math.min(frame, c.angles.length - 1);
      const reach = camReach(c);
      if (!view || !camDrag && outside({ extent: reach })) view = fit({ extent: reach });
    }
    draw();
    document.body.dataset.state = "valid";
  }

  $("fullrun").addEventListener("click", () => recompute(true));

  $("save").addEventListener("click", async () => {
    const name = $("saveas").value.trim();
    const answer = await api("/api/save", name ? { values, name } : { values });
    $("saved").textContent = answer.ok ? `saved to ${answer.saved}` : answer.message;
    $("saved").className = answer.ok ? "ok" : "error";
  });

  // ------------------------------------------------------------------ the view
  function fit(s) {
    const [x0, x1, y0, y1] = s.extent;
    const pad = 0.12 * Math.max(x1 - x0, y1 - y0, 1e-9);
    const k = Math.min(W / (x1 - x0 + 2 * pad), H / (y1 - y0 + 2 * pad));
    return { k, cx: (x0 + x1) / 2, cy: (y0 + y1) / 2 };
  }

  function outside(s) {
    const [x0, x1, y0, y1] = s.extent;
    const [a, b] = [sx(x0), sy(y0)], [c, d] = [sx(x1), sy(y1)];
    return a < 0 || c > W || d < 0 || b > H;
  }

  const sx = (x) => W / 2 + (x - view.cx) * view.k;
  const sy = (y) => H / 2 - (y - view.cy) * view.k;

  function at(name, i) {
    const s = last.scene;
    if (name.startsWith("ground:")) {
      const g = s.ground.find((p) => "ground:" + p.name === name);
      return g ? [g.x, g.y] : null;
    }
    const p = s.points[name];
    return p && p[0][i] !== null ? [p[0][i], p[1][i]] : null;
  }

  function draw() {
    const svg = $("view");
    if (last && last.cam) {
      drawCam(svg, last.cam, frame, view);
      $("slider").value = frame;
      drawPlots();
      if (comparing) drawComparison();
      return;
    }
    if (!last || !last.scene) { svg.textContent = ""; drawPlots(); return; }
    $("angle").textContent = `${fmt(last.scene.angles[frame])}°`;
    drawMachine(svg, last.scene, view, frame, last.drags);
    $("slider").value = frame;
    drawPlots();
    if (comparing) drawComparison();
  }

  // the machine of scene s at position i in svg, seen through v (scale and centre); handles where drags allow
  function drawMachine(svg, s, v, i, drags) {
    svg.textContent = "";
    const X = (x) => W / 2 + (x - v.cx) * v.k, Y = (y) => H / 2 - (y - v.cy) * v.k;
    const pt = (name) => {
      if (name.startsWith("ground:")) {
        const g = s.ground.find((p) => "ground:" + p.name === name);
        return g ? [g.x, g.y] : null;
      }
      const p = s.points[name];
      return p && p[0][i] !== null ? [p[0][i], p[1][i]] : null;
    };
    for (const t of s.traces) {
      const [xs, ys] = s.points[t];
      const d = xs.map((x, j) => x === null ? "" : `${X(x).toFixed(1)},${Y(ys[j]).toFixed(1)}`).filter(Boolean).join(" ");
      el("polyline", { points: d, fill: "none", stroke: "#9ab", "stroke-dasharray": "3 3" }, svg);
    }
    for (const g of s.guides) el("line", { x1: X(g[0]), y1: Y(g[1]), x2: X(g[2]), y2: Y(g[3]), stroke: "#888", "stroke-width": 3 }, svg);
    for (const b of s.bodies) {
      const pts = b.points.map((p) => pt(`${b.name}.${p}`)).filter(Boolean);
      if (!pts.length) continue;
      if (b.shape === "slider") {
        const [x, y] = pts[0];
        const r = el("rect", { x: X(x) - 16, y: Y(y) - 9, width: 32, height: 18, fill: b.colour, "fill-opacity": 0.5, stroke: b.colour }, svg);
        if (b.angle) r.setAttribute("transform", `rotate(${-b.angle[i]} ${X(x)} ${Y(y)})`);
      } else {
        el("polygon", { points: pts.map(([x, y]) => `${X(x)},${Y(y)}`).join(" "), fill: b.colour, "fill-opacity": b.shape === "polygon" ? 0.25 : 0,
          stroke: b.colour, "stroke-width": 5, "stroke-linejoin": "round" }, svg);
      }
    }
    for (const g of s.ground) {
      const x = X(g.x), y = Y(g.y);
      el("path", { d: `M${x},${y} l-9,15 h18 z`, fill: "#ccc", stroke: "#555" }, svg);
    }
    const handles = new Set((drags || []).flatMap((r) => r.points));
    const drawn = new Set();
    for (const [name] of Object.entries(s.points)) {
      const p = pt(name);
      if (!p) continue;
      const key = `${X(p[0]).toFixed(0)},${Y(p[1]).toFixed(0)}`;
      const handle = handles.has(name);
      if (drawn.has(key) && !handle) continue;
      drawn.add(key);
      const c = el("circle", { cx: X(p[0]), cy: Y(p[1]), r: handle ? 7 : 4, fill: handle ? "#fff" : "#333", stroke: "#333", "data-point": name }, svg);
      if (handle) c.classList.add("handle");
    }
    for (const g of s.ground) {
      if (!handles.has("ground:" + g.name)) continue;
      el("circle", { cx: X(g.x), cy: Y(g.y), r: 7, fill: "#fff", stroke: "#333", class: "handle", "data-point": "ground:" + g.name }, svg);
    }
    for (const g of s.ground) {
      const t = el("text", { x: X(g.x) + 10, y: Y(g.y) + 26, "font-size": 12, fill: "#555" }, svg);
      t.textContent = g.name;
    }
  }

  // ------------------------------------------------------------------ variants side by side
  let comparing = null;

  function variantList(names) {
    for (const id of ["vara", "varb"]) {
      const sel = $(id), kept = sel.value;
      sel.textContent = "";
      for (const n of names) { const o = document.createElement("option"); o.value = o.textContent = n; sel.appendChild(o); }
      if (names.includes(kept)) sel.value = kept;
    }
    if (names.length > 1 && $("vara").value === $("varb").value) $("varb").value = names[names.length - 1];
    $("compare").disabled = names.length < 2;
    $("variants").dataset.count = String(names.length);
  }

  $("keep").addEventListener("click", async () => {
    const name = $("varname").value.trim() || `variant ${Number($("variants").dataset.count || 0) + 1}`;
    const answer = await api("/api/variant", { name, values });
    $("varmsg").textContent = answer.ok ? `kept “${name}”` : answer.message;
    $("varmsg").className = answer.ok ? "ok" : "error";
    if (answer.ok) { variantList(answer.variants); $("varname").value = ""; }
  });

  $("compare").addEventListener("click", async () => {
    const answer = await api("/api/compare", { a: $("vara").value, b: $("varb").value });
    if (!answer.ok) { $("varmsg").textContent = answer.message; $("varmsg").className = "error"; return; }
    comparing = answer;
    $("comparison").hidden = false;
    drawComparison();
  });
  $("closecompare").addEventListener("click", () => { comparing = null; $("comparison").hidden = true; });

  function drawComparison() {
    const c = comparing;
    const sa = c.a.answer.scene, sb = c.b.answer.scene, ca = c.a.answer.cam, cb = c.b.answer.cam;
    $("cmpa").textContent = c.a.name; $("cmpb").textContent = c.b.name;
    for (const id of ["viewa", "viewb"]) $(id).textContent = "";
    if (ca && cb) {  // two cams at one scale, at the cam angle of the slider
      const ea = camReach(ca), eb = camReach(cb);
      const v = fit({ extent: [Math.min(ea[0], eb[0]), Math.max(ea[1], eb[1]), Math.min(ea[2], eb[2]), Math.max(ea[3], eb[3])] });
      drawCam($("viewa"), ca, Math.min(frame, ca.angles.length - 1), v);
      drawCam($("viewb"), cb, Math.min(frame, cb.angles.length - 1), v);
      $("cmpscale").textContent = `one scale: ${fmt(100 / v.k * 1000)} mm per 100 px`;
    }
    if (sa && sb) {  // one scale: the union of both machines' extents
      const e = [Math.min(sa.extent[0], sb.extent[0]), Math.max(sa.extent[1], sb.extent[1]),
        Math.min(sa.extent[2], sb.extent[2]), Math.max(sa.extent[3], sb.extent[3])];
      const v = fit({ extent: e });
      for (const [id, s] of [["viewa", sa], ["viewb", sb]]) {
        const i = Math.round(frame / Math.max(1, (last && last.scene ? last.scene.angles.length : 1) - 1) * (s.angles.length - 1)) || 0;
        drawMachine($(id), s, v, Math.min(i, s.angles.length - 1), []);
      }
      $("cmpscale").textContent = `one scale: ${fmt(100 / v.k * 1000)} mm per 100 px`;
    }
    const fields = $("cmpfields");
    fields.textContent = c.fields.length ? "Fields that differ: " + c.fields.map((f) => `${f.key} ${f.a} → ${f.b}`).join("; ") : "The two variants have the same values.";
    const body = $("cmptable").tBodies[0];
    body.textContent = "";
    for (const r of c.rows) {
      const row = body.insertRow();
      row.insertCell().textContent = r.label;
      for (const v of [r.a, r.b, r.difference]) { const cell = row.insertCell(); cell.textContent = fmt(v); cell.className = "value"; }
      const rel = row.insertCell(); rel.className = "value";
      rel.textContent = r.relative === null ? "–" : `${r.relative >= 0 ? "+" : ""}${(100 * r.relative).toFixed(1)} %`;
      row.insertCell().textContent = r.unit;
      if (r.difference !== 0) row.className = "differs";
    }
  }

  // ------------------------------------------------------------------ plots
  function plot(title, unit, series, angles, extra) {
    const w = 640, h = 170, l = 56, r = 10, t = 20, b = 24;
    const svg = el("svg", { viewBox: `0 0 ${w} ${h}`, class: "plot", "data-title": title });
    const all = series.flatMap((s) => s.ys).filter((v) => v !== null);
    if (!all.length) return svg;
    let lo = Math.min(0, ...all), hi = Math.max(0, ...all);
    if (hi === lo) hi = lo + 1;
    const a0 = angles[0], a1 = angles[angles.length - 1] || a0 + 1;
    const px = (a) => l + (a - a0) / (a1 - a0 || 1) * (w - l - r), py = (v) => t + (hi - v) / (hi - lo) * (h - t - b);
    el("line", { x1: l, x2: w - r, y1: py(0), y2: py(0), stroke: "#bbb" }, svg);
    for (const [v, anchor] of [[hi, py(hi) + 4], [lo, py(lo)]]) {
      const tx = el("text", { x: l - 4, y: anchor, "text-anchor": "end", "font-size": 11 }, svg); tx.textContent = fmt(v);
    }
    const head = el("text", { x: l, y: 14, "font-size": 12, "font-weight": "bold" }, svg);
    head.textContent = `${title} [${unit}]` + (series.length > 1 ? ":  " + series.map((s) => s.name).join(", ") : "");
    for (const [a, anchor] of [[a0, "start"], [a1, "end"]]) {
      const tx = el("text", { x: px(a), y: h - 6, "text-anchor": anchor, "font-size": 11 }, svg); tx.textContent = `${fmt(a)}°`;
    }
    series.forEach((s, k) => {
      const d = s.ys.map((v, i) => v === null ? "" : `${px(angles[i]).toFixed(1)},${py(v).toFixed(1)}`).filter(Boolean).join(" ");
      el("polyline", { points: d, fill: "none", stroke: s.colour || ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"][k % 6], "stroke-width": 1.5 }, svg);
    });
    const x = px(angles[frame]);
    el("line", { x1: x, x2: x, y1: t, y2: h - b, stroke: "#555", "stroke-dasharray": "2 2" }, svg);
    // from a pointer to the plot's own numbers (angle, value), at the scale it was drawn with
    svg.inverse = (e) => {
      const box = svg.getBoundingClientRect();
      const X = (e.clientX - box.left) * w / box.width, Y = (e.clientY - box.top) * h / box.height;
      return [a0 + (X - l) / (w - l - r) * (a1 - a0), hi - (Y - t) / (h - t - b) * (hi - lo)];
    };
    if (extra) extra(svg, px, py);
    svg.addEventListener("click", (e) => {
      if (e.target.classList && e.target.classList.contains("handle")) return;
      const box = svg.getBoundingClientRect();
      const a = a0 + ((e.clientX - box.left) * w / box.width - l) / (w - l - r) * (a1 - a0);
      let best = 0;
      angles.forEach((v, i) => { if (Math.abs(v - a) < Math.abs(angles[best] - a)) best = i; });
      frame = best; draw();
    });
    return svg;
  }

  function drawPlots() {
    const box = $("plots");
    if (last && last.cam) { camPlots(box, last.cam); return; }
    box.textContent = "";
    if (!last || !last.scene) return;
    const s = last.scene;
    for (const c of s.curves) box.appendChild(plot(c.title, c.unit, [{ name: c.title, ys: c.y }], s.angles));
    if (s.joints.length) {
      const series = s.joints.map((j) => ({ name: j.name, ys: j.fx.map((fx, i) => fx === null || j.fy[i] === null ? null : Math.hypot(fx, j.fy[i])) }));
      box.appendChild(plot("Joint forces |F|", "N", series, s.angles));
    }
  }

  // ------------------------------------------------------------------ a cam: its profile turning, its diagrams
  let camDrag = null;

  function camReach(c) {  // a square around the cam and its follower's travel (and an oscillating one's pivot)
    let r = c.pivot ? Math.abs(c.pivot[0]) : c.base_radius;
    for (const [xs, ys] of [c.surface, c.pitch]) xs.forEach((x, i) => { if (x !== null) r = Math.max(r, Math.hypot(x, ys[i])); });
    r += c.roller_radius;
    return [-1.15 * r, 1.15 * r, -1.15 * r, 1.6 * r];
  }

  function drawCam(svg, c, i, v) {
    svg.textContent = "";
    const X = (x) => W / 2 + (x - v.cx) * v.k, Y = (y) => H / 2 - (y - v.cy) * v.k;
    const a = c.turn * c.angles[i] * Math.PI / 180, ca = Math.cos(a), sa = Math.sin(a);
    const turned = (x, y) => [ca * x - sa * y, sa * x + ca * y];  // F = R(theta) P: the cam turned by theta
    const line = ([xs, ys]) => xs.map((x, j) => x === null ? "" : turned(x, ys[j])).filter(Boolean)
      .map(([x, y]) => `${X(x).toFixed(1)},${Y(y).toFixed(1)}`).join(" ");
    el("circle", { cx: X(0), cy: Y(0), r: c.base_radius * v.k, fill: "none", stroke: "#bbb", "stroke-dasharray": "4 3" }, svg);
    el("polygon", { points: line(c.surface), fill: "#c8d8ea", stroke: "#1f4e79", "stroke-width": 2, "data-part": "cam" }, svg);
    if (c.contact === "roller") el("polygon", { points: line(c.pitch), fill: "none", stroke: "#9ab", "stroke-dasharray": "3 3" }, svg);
    el("circle", { cx: X(0), cy: Y(0), r: 4, fill: "#333" }, svg);
    const [px, py] = turned(c.pitch[0][i], c.pitch[1][i]);
    if (c.contact === "flat") {
      el("line", { x1: X(px) - 60, x2: X(px) + 60, y1: Y(py), y2: Y(py), stroke: "#d62728", "stroke-width": 4 }, svg);
      el("line", { x1: X(0), x2: X(0), y1: Y(py), y2: Y(py) - 70, stroke: "#d62728", "stroke-width": 6 }, svg);
    } else if (c.pivot) {  // an oscillating follower: its arm from the pivot to the roller
      el("line", { x1: X(c.pivot[0]), x2: X(px), y1: Y(c.pivot[1]), y2: Y(py), stroke: "#d62728", "stroke-width": 6 }, svg);
      el("path", { d: `M${X(c.pivot[0])},${Y(c.pivot[1])} l-9,15 h18 z`, fill: "#ccc", stroke: "#555" }, svg);
      el("circle", { cx: X(px), cy: Y(py), r: Math.max(3, c.roller_radius * v.k), fill: "#fff", stroke: "#d62728", "stroke-width": 2 }, svg);
    } else {
      el("line", { x1: X(px), x2: X(px), y1: Y(py), y2: Y(py) - 70, stroke: "#d62728", "stroke-width": 6 }, svg);
      el("circle", { cx: X(px), cy: Y(py), r: Math.max(3, c.roller_radius * v.k), fill: "#fff", stroke: "#d62728", "stroke-width": 2 }, svg);
    }
    if (svg === $("view")) $("angle").textContent = `${fmt(c.angles[i])}°`;
  }

  function camPlots(box, c) {
    const [disp, ...rest] = c.curves;
    if (camDrag) {  // the diagram being dragged stays, at the drag's scale, until the drop; the others follow
      for (const child of [...box.children]) if (child !== camDrag.svg) child.remove();
    } else box.textContent = "";
    if (!camDrag) box.appendChild(plot(disp.title, disp.unit, [{ name: disp.title, ys: disp.y }], c.angles, (svg, px, py) => {
      svg.id = "diagram";
      c.points.forEach((p, k) => {
        const movable = p.x.length || p.y.length;
        const h = el("circle", { cx: px(p.theta), cy: py(p.s), r: movable ? 7 : 4, fill: movable ? "#fff" : "#333",
          stroke: "#333", "data-point": String(k) }, svg);
        if (movable) { h.classList.add("handle"); h.addEventListener("pointerdown", (e) => camGrab(e, svg, p, k)); }
      });
    }));
    for (const r of rest) {
      const limit = r.title === "Pressure angle" ? (svg, px, py) => {
        for (const y of [c.pressure_angle_limit, -c.pressure_angle_limit]) el("line", { x1: px(c.angles[0]), x2: px(c.angles[c.angles.length - 1]), y1: py(y), y2: py(y), stroke: "#c00", "stroke-dasharray": "5 3" }, svg);
      } : undefined;
      box.appendChild(plot(r.title, r.unit, [{ name: r.title, ys: r.y }], c.angles, limit));
    }
  }

  // a program point dragged: sideways moves its boundary, up or down its stroke end, from where it was grabbed
  function camGrab(e, svg, p, k) {
    const [a0, s0] = svg.inverse(e);
    camDrag = { svg, p, k, a0, s0, from: Object.fromEntries([...p.x, ...p.y].map((r) => [r.key, Number(values[r.key])])) };
    record();
    svg.setPointerCapture(e.pointerId);
    svg.addEventListener("pointermove", camMove);
    const drop = () => { camDrag = null; svg.removeEventListener("pointermove", camMove); draw(); };
    svg.addEventListener("pointerup", drop, { once: true });
    svg.addEventListener("pointercancel", drop, { once: true });
    e.preventDefault(); e.stopPropagation();
  }

  function camMove(e) {
    if (!camDrag) return;
    const [a, s] = camDrag.svg.inverse(e), p = camDrag.p;
    const perUnit = p.unit === "deg" ? Math.PI / 180 : 1e-3;  // the diagram's units in SI
    const dx = (a - camDrag.a0) * Math.PI / 180, dy = (s - camDrag.s0) * perUnit;
    // one change for all the fields of an axis, rounded once (to 0.001 of the field's unit), so that the angles
    // still add up to 360 deg and the lifts still close the cycle, exactly as typed numbers would
    for (const [rules, d] of [[p.x, dx], [p.y, dy]]) {
      if (!rules.length) continue;
      const step = Math.round(d / rules[0].si * 1000) / 1000;
      for (const r of rules) {
        setField(r.key, 0, String(Number((camDrag.from[r.key] + r.sign * step).toFixed(3))));
      }
    }
    const handle = camDrag.svg.querySelector(`circle[data-point="${camDrag.k}"]`);
    if (handle) {  // the handle follows the pointer (along the axes that move)
      const box = camDrag.svg.getBoundingClientRect(), vb = camDrag.svg.viewBox.baseVal;
      if (p.x.length) handle.setAttribute("cx", (e.clientX - box.left) * vb.width / box.width);
      if (p.y.length) handle.setAttribute("cy", (e.clientY - box.top) * vb.height / box.height);
    }
    edited(e);
  }

  // ------------------------------------------------------------------ slider, play, drag
  $("slider").addEventListener("input", () => { frame = Number($("slider").value); draw(); });
  $("fit").addEventListener("click", () => {
    if (last && last.scene) view = fit(last.scene); else if (last && last.cam) view = fit({ extent: camReach(last.cam) });
    draw();
  });
  $("play").addEventListener("click", () => {
    playing = !playing;
    $("play").textContent = playing ? "Pause" : "Play";
    const step = () => {
      const angles = last && (last.scene || last.cam) ? (last.scene || last.cam).angles : null;
      if (!playing || !angles) return;
      frame = (frame + 1) % angles.length;
      draw();
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  });

  function world(e) {
    const box = $("view").getBoundingClientRect();
    const x = (e.clientX - box.left) * W / box.width, y = (e.clientY - box.top) * H / box.height;
    return [view.cx + (x - W / 2) / view.k, view.cy - (y - H / 2) / view.k];
  }

  function setField(key, number, text) {
    values[key] = text === undefined ? String(Number(number.toPrecision(5))) : text;
    const row = [...$("fields").tBodies[0].rows].find((r) => r.dataset.key === key);
    if (row) for (const input of row.querySelectorAll("input")) input.value = values[key];
  }

  $("view").addEventListener("pointerdown", (e) => {
    const name = e.target.getAttribute && e.target.getAttribute("data-point");
    const rule = name && last && last.drags.find((r) => r.points.includes(name));
    if (!rule || !last.scene) return;
    // the reference points stay those of the frame where the drag began
    drag = { rule, refs: Object.fromEntries(rule.set.map((s) => [s.from, at(s.from, frame)])) };
    record();
    $("view").setPointerCapture(e.pointerId);
    e.preventDefault();
  });
  $("view").addEventListener("pointermove", (e) => {
    if (!drag) return;
    const [x, y] = world(e);
    for (const s of drag.rule.set) {
      const q = drag.refs[s.from];
      if (!q) continue;
      const value = s.measure === "angle" ? Math.atan2(y - q[1], x - q[0]) : Math.hypot(x - q[0], y - q[1]);
      setField(s.key, value / s.si);
    }
    recompute();
  });
  const drop = () => { drag = null; };
  $("view").addEventListener("pointerup", drop);
  $("view").addEventListener("pointercancel", drop);

  // ------------------------------------------------------------------ start
  (async function start() {
    const state = await api("/api/state");
    if (!state.fields) { $("status").textContent = state.message || "the studio could not open the file"; return; }
    fields = state.fields;
    $("file").textContent = state.file;
    buildFields(state.editable);
    if (!state.editable) {
      $("readonly").hidden = false;
      $("report").href = "/report?token=" + encodeURIComponent(token);
      for (const id of ["undo", "redo", "save", "saveas"]) $(id).disabled = true;
    }
    document.body.dataset.busy = "0";
    show(state.result);
    document.body.dataset.ready = "1";
  })();
})();
