/* machdyn report views: the animated mechanism and the interactive design space.
   Plain SVG and DOM, no library and no network. Each <div class="mdview"> carries its data as JSON. Mechanism
   drawings are in world coordinates (metres, y up: a flip in the group transform), so a joint's cx/cy are its
   position in metres. window.machdynViews lists the views' controllers (set(i), play(), pause(), index). */
(function () {
  "use strict";
  var NS = "http://www.w3.org/2000/svg";
  window.machdynViews = window.machdynViews || [];

  function el(tag, attrs, parent) {
    var node = document.createElementNS(NS, tag);
    for (var k in attrs) { if (attrs[k] !== undefined && attrs[k] !== null) node.setAttribute(k, attrs[k]); }
    if (parent) parent.appendChild(node);
    return node;
  }
  function html(tag, attrs, parent, text) {
    var node = document.createElement(tag);
    for (var k in attrs) node.setAttribute(k, attrs[k]);
    if (text !== undefined) node.textContent = text;
    if (parent) parent.appendChild(node);
    return node;
  }
  function fmt(v) {
    if (v === null || v === undefined || !isFinite(v)) return "–";
    var a = Math.abs(v);
    if (a !== 0 && (a >= 1e5 || a < 1e-3)) return v.toExponential(3);
    return Number(v.toPrecision(4)).toString();
  }
  function maxAbs(arrays) {
    var m = 0;
    arrays.forEach(function (arr) { arr.forEach(function (v) { if (v !== null && Math.abs(v) > m) m = Math.abs(v); }); });
    return m;
  }

  /* ------------------------------------------------------------------ one mechanism drawing */
  function jointMax(s) {
    return maxAbs(s.joints.map(function (j) { return j.fx; }).concat(s.joints.map(function (j) { return j.fy; })));
  }
  function shakeMax(s) { return s.shaking ? maxAbs([s.shaking.fx, s.shaking.fy]) : 0; }

  /* scale: the largest force component of the joints and of the shaking force over every scene shown together,
     so that arrows compare across scenes */
  function Drawing(parent, s, scale) {
    var ext = s.extent, span = Math.max(ext[1] - ext[0], ext[3] - ext[2], 1e-9), pad = 0.18 * span;
    var vb = [ext[0] - pad, -(ext[3] + pad), ext[1] - ext[0] + 2 * pad, ext[3] - ext[2] + 2 * pad];
    var wrap = html("div", { "class": "mdview-scene" }, parent);
    if (s.title) html("div", { "class": "mdview-title" }, wrap, s.title);
    var svg = el("svg", { viewBox: vb.join(" "), "class": "mdview-svg", role: "img",
                          "aria-label": "animated mechanism" }, wrap);
    var defs = el("defs", {}, svg);
    ["joint", "shake"].forEach(function (kind) {
      var m = el("marker", { id: parent.id + "-" + kind + "-head", viewBox: "0 0 10 10", refX: 9, refY: 5,
                             markerWidth: 6, markerHeight: 6, orient: "auto-start-reverse" }, defs);
      el("path", { d: "M0,0 L10,5 L0,10 z", "class": "mdview-head-" + kind }, m);
    });
    var g = el("g", { transform: "scale(1,-1)" }, svg);
    var r = 0.012 * span, arrowLen = 0.3 * span;
    s.guides.forEach(function (q) {
      el("line", { x1: q[0], y1: q[1], x2: q[2], y2: q[3], "class": "mdview-guide" }, g);
    });
    s.traces.forEach(function (key) {
      var p = s.points[key], pts = [];
      for (var i = 0; i < p[0].length; i++) if (p[0][i] !== null) pts.push(p[0][i] + "," + p[1][i]);
      el("polyline", { points: pts.join(" "), "class": "mdview-trace", "data-trace": key }, g);
    });
    s.ground.forEach(function (p) {
      var h = 2.2 * r;
      el("path", { d: "M" + p.x + "," + p.y + " l" + (-h) + "," + (-1.6 * h) + " h" + 2 * h + " z",
                   "class": "mdview-ground" }, g);
    });
    var shapes = s.bodies.map(function (b) {
      var node = b.shape === "link" ? el("polyline", { "class": "mdview-link", stroke: b.colour }, g)
        : el("polygon", { "class": "mdview-body" + (b.shape === "frame" ? " mdview-housing" : ""), fill: b.colour,
                          stroke: b.colour, "data-body": b.name }, g);
      node.setAttribute("data-body", b.name);
      return node;
    });
    var jointDots = {}, dotOrder = [];
    s.bodies.forEach(function (b) {
      b.points.forEach(function (p, k) {
        var key = b.name + "." + p;
        if (b.dots === false) return;  /* a body drawn by its outline alone (a cam's profile) */
        /* a roller: its first point drawn as a circle of its own radius, in metres */
        var radius = (b.roller && k === 0) ? b.roller : r;
        jointDots[key] = el("circle", { r: radius, "class": "mdview-point", "data-point": key }, g);
        dotOrder.push(key);
      });
    });
    var massDots = (s.masses || []).map(function (m) {
      var dot = el("circle", { r: (0.6 + 1.4 * m.size) * 2 * r, "class": "mdview-mass", "data-mass": m.name }, g);
      el("title", {}, dot).textContent = m.name + ": " + fmt(m.mass) + " kg";
      return dot;
    });
    s.ground.forEach(function (p) {
      el("circle", { cx: p.x, cy: p.y, r: r, "class": "mdview-pivot", "data-ground": p.name }, g);
    });
    var fmax = Math.max(scale.joint * Math.SQRT2, 1e-300);
    var arrows = s.joints.map(function (j) {
      return el("line", { "class": "mdview-force", "marker-end": "url(#" + parent.id + "-joint-head)",
                          "data-joint": j.name }, g);
    });
    var shake = null, smax = 1e-300;
    if (s.shaking) {
      smax = Math.max(scale.shake * Math.SQRT2, 1e-300);
      shake = el("line", { "class": "mdview-shake", "marker-end": "url(#" + parent.id + "-shake-head)" }, g);
    }
    var table = html("table", { "class": "mdview-values" }, wrap);

    function pos(key, i) { var p = s.points[key]; return [p[0][i], p[1][i]]; }
    this.show = function (i) {
      s.bodies.forEach(function (b, k) {
        var pts = b.points.map(function (p) { return pos(b.name + "." + p, i); });
        if (pts.some(function (p) { return p[0] === null; })) { shapes[k].setAttribute("visibility", "hidden"); return; }
        shapes[k].setAttribute("visibility", "visible");
        if (b.shape === "slider") {
          var a = b.angle[i] * Math.PI / 180, c = Math.cos(a), sn = Math.sin(a), w = 0.05 * span, h = 0.03 * span;
          var x = pts[0][0], y = pts[0][1];
          pts = [[-w, -h], [w, -h], [w, h], [-w, h]].map(function (q) {
            return [x + c * q[0] - sn * q[1], y + sn * q[0] + c * q[1]];
          });
        } else if (b.shape === "polygon" || b.shape === "frame") {
          var mx = 0, my = 0;
          pts.forEach(function (p) { mx += p[0]; my += p[1]; });
          mx /= pts.length; my /= pts.length;
          pts.sort(function (p, q) { return Math.atan2(p[1] - my, p[0] - mx) - Math.atan2(q[1] - my, q[0] - mx); });
        }
        shapes[k].setAttribute("points", pts.map(function (p) { return p[0] + "," + p[1]; }).join(" "));
      });
      dotOrder.forEach(function (key) {
        var p = pos(key, i), dot = jointDots[key];
        if (!dot) return;
        if (p[0] === null) { dot.setAttribute("visibility", "hidden"); return; }
        dot.setAttribute("visibility", "visible");
        dot.setAttribute("cx", p[0]);
        dot.setAttribute("cy", p[1]);
      });
      (s.masses || []).forEach(function (m, k) {
        var x = m.at[0][i], y = m.at[1][i];
        if (x === null) { massDots[k].setAttribute("visibility", "hidden"); return; }
        massDots[k].setAttribute("visibility", "visible");
        massDots[k].setAttribute("cx", x); massDots[k].setAttribute("cy", y);
      });
      var rows = [];
      s.joints.forEach(function (j, k) {
        var p = pos(j.at, i), fx = j.fx[i], fy = j.fy[i];
        if (p[0] === null || fx === null) { arrows[k].setAttribute("visibility", "hidden"); return; }
        arrows[k].setAttribute("visibility", Math.hypot(fx, fy) > 1e-9 * fmax ? "visible" : "hidden");
        arrows[k].setAttribute("x1", p[0]); arrows[k].setAttribute("y1", p[1]);
        arrows[k].setAttribute("x2", p[0] + fx / fmax * arrowLen); arrows[k].setAttribute("y2", p[1] + fy / fmax * arrowLen);
        rows.push(["Joint " + j.name, fmt(Math.hypot(fx, fy)), "N"]);
      });
      if (shake) {
        var fx = s.shaking.fx[i], fy = s.shaking.fy[i], at = s.shaking.at;
        /* a force that vanishes to round-off (a balanced machine) has no direction worth an arrowhead */
        shake.setAttribute("visibility", Math.hypot(fx, fy) > 1e-9 * smax ? "visible" : "hidden");
        shake.setAttribute("x1", at[0]); shake.setAttribute("y1", at[1]);
        shake.setAttribute("x2", at[0] + fx / smax * arrowLen); shake.setAttribute("y2", at[1] + fy / smax * arrowLen);
        rows.push(["Inertial shaking force", fmt(Math.hypot(fx, fy)), "N"]);
        rows.push(["Shaking moment", fmt(s.shaking.moment[i]), "N·m"]);
      }
      table.textContent = "";
      rows.forEach(function (row) {
        var tr = html("tr", {}, table);
        row.forEach(function (cell, c) { html(c === 0 ? "th" : "td", {}, tr, cell); });
      });
    };
  }

  /* ------------------------------------------------------------------ one curve against the crank angle */
  function CurvePlot(parent, angles, c, onPick, range, axis) {
    var W = 300, H = 130, L = 46, R = 8, T = 18, B = 22;
    var svg = el("svg", { viewBox: "0 0 " + W + " " + H, "class": "mdview-curve", "data-curve": c.title }, parent);
    var ys = c.y.filter(function (v) { return v !== null; });
    var base = c.zero === false ? [] : [0];
    var lo = Math.min.apply(null, ys.concat(base)), hi = Math.max.apply(null, ys.concat(base));
    if (range) { lo = Math.min(lo, range[0]); hi = Math.max(hi, range[1]); }
    if (hi - lo < 1e-9 * Math.max(Math.abs(hi), Math.abs(lo), 1e-300) || hi === lo) { hi = lo + 1; }
    if (hi === lo) { hi = lo + 1; }
    var a0 = angles[0], a1 = angles[angles.length - 1];
    if (a1 === a0) a1 = a0 + 1;
    function px(a) { return L + (a - a0) / (a1 - a0) * (W - L - R); }
    function py(v) { return T + (hi - v) / (hi - lo) * (H - T - B); }
    el("text", { x: L, y: 12, "class": "mdview-curve-title" }, svg).textContent = c.title + " [" + c.unit + "]";
    el("line", { x1: L, y1: py(0), x2: W - R, y2: py(0), "class": "mdview-axis" }, svg);
    el("text", { x: L - 4, y: py(hi) + 4, "class": "mdview-tick", "text-anchor": "end" }, svg).textContent = fmt(hi);
    el("text", { x: L - 4, y: py(lo), "class": "mdview-tick", "text-anchor": "end" }, svg).textContent = fmt(lo);
    /* the frames' axis: the crank angle, or another (a transient's time) named by the scene's "axis" */
    var unit = axis ? " " + axis.unit : "°", what = axis ? " " + axis.name : " crank";
    el("text", { x: L, y: H - 6, "class": "mdview-tick" }, svg).textContent = fmt(a0) + unit;
    el("text", { x: W - R, y: H - 6, "class": "mdview-tick", "text-anchor": "end" }, svg).textContent = fmt(a1) + unit + what;
    var pts = [];
    c.y.forEach(function (v, i) { if (v !== null) pts.push(px(angles[i]).toFixed(2) + "," + py(v).toFixed(2)); });
    el("polyline", { points: pts.join(" "), "class": "mdview-curve-line" }, svg);
    var cursor = el("line", { y1: T - 4, y2: H - B, "class": "mdview-cursor" }, svg);
    var dot = el("circle", { r: 3, "class": "mdview-cursor-dot" }, svg);
    var value = el("text", { x: W - R, y: T + 8, "class": "mdview-tick mdview-curve-value", "text-anchor": "end" }, svg);
    svg.addEventListener("click", function (ev) {
      var box = svg.getBoundingClientRect(), x = (ev.clientX - box.left) / box.width * W;
      var a = a0 + (x - L) / (W - L - R) * (a1 - a0), best = 0;
      angles.forEach(function (v, i) { if (Math.abs(v - a) < Math.abs(angles[best] - a)) best = i; });
      onPick(best);
    });
    this.show = function (i) {
      var x = px(angles[i]);
      cursor.setAttribute("x1", x); cursor.setAttribute("x2", x); cursor.setAttribute("data-index", i);
      if (c.y[i] !== null) { dot.setAttribute("cx", x); dot.setAttribute("cy", py(c.y[i])); }
      value.textContent = fmt(c.y[i]) + " " + c.unit;
    };
  }

  /* ------------------------------------------------------------------ the mechanism view */
  function MechanismView(root, data, order) {
    var names = Object.keys(data.scenes), first = data.scenes[names[0]], angles = first.angles, n = angles.length;
    var self = this, timer = null;
    self.root = root; self.index = 0; self.size = n;
    var bar = html("div", { "class": "mdview-controls" }, root);
    var play = html("button", { type: "button", "class": "mdview-play" }, bar, "▶ play");
    var slider = html("input", { type: "range", min: 0, max: n - 1, step: 1, value: 0, "class": "mdview-slider",
                                 "aria-label": "crank angle" }, bar);
    var readout = html("span", { "class": "mdview-angle" }, bar);
    var speed = html("select", { "class": "mdview-speed", "aria-label": "playback speed" }, bar);
    [["0.25", "¼×"], ["0.5", "½×"], ["1", "1×"], ["2", "2×"], ["4", "4×"]].forEach(function (o) {
      var opt = html("option", { value: o[0] }, speed, o[1]);
      if (o[0] === "1") opt.selected = true;
    });
    var track = el("svg", { viewBox: "0 0 1000 14", preserveAspectRatio: "none", "class": "mdview-track" }, root);
    var a0 = angles[0], a1 = angles[n - 1] === a0 ? a0 + 1 : angles[n - 1];
    (first.marks || []).forEach(function (m) {
      var x = (m.angle - a0) / (a1 - a0) * 1000;
      if (x < -1 || x > 1001) return;
      var t = el("rect", { x: x - 3, y: 0, width: 6, height: 14, "class": "mdview-mark mdview-mark-" + m.kind,
                           "data-angle": m.angle }, track);
      el("title", {}, t).textContent = m.label + " at " + fmt(m.angle) + "°";
      t.addEventListener("click", function () { self.set(nearest(m.angle)); });
    });
    var legend = html("div", { "class": "mdview-legend" }, root);
    legend.innerHTML = '<span class="mdview-key-force"></span> joint reaction &nbsp; ' +
      '<span class="mdview-key-shake"></span> inertial shaking force on the frame &nbsp; ' +
      '<span class="mdview-key-mark mdview-mark-dead"></span> dead &nbsp;<span class="mdview-key-mark mdview-mark-limit">' +
      '</span> limit &nbsp;<span class="mdview-key-mark mdview-mark-transmission"></span> worst transmission angle';
    var row = html("div", { "class": "mdview-row" }, root);
    var scale = { joint: 0, shake: 0 };
    names.forEach(function (k) {
      scale.joint = Math.max(scale.joint, jointMax(data.scenes[k]));
      scale.shake = Math.max(scale.shake, shakeMax(data.scenes[k]));
    });
    var drawings = names.map(function (k) {
      var sc = data.scenes[k];
      if (!sc.title && names.length > 1) sc.title = k;
      return new Drawing(row, sc, scale);
    });
    var curveRow = html("div", { "class": "mdview-curves" }, root);
    var curves = [], ranges = {};
    names.forEach(function (k) {
      data.scenes[k].curves.forEach(function (c) {
        var ys = c.y.filter(function (v) { return v !== null; }), r = ranges[c.title] || [ys[0], ys[0]];
        ranges[c.title] = [Math.min.apply(null, ys.concat([r[0]])), Math.max.apply(null, ys.concat([r[1]]))];
      });
    });
    names.forEach(function (k) {
      data.scenes[k].curves.forEach(function (c) {
        var shown = names.length > 1 ? { title: c.title + " (" + k + ")", unit: c.unit, y: c.y, zero: c.zero } : c;
        curves.push(new CurvePlot(curveRow, angles, shown, function (i) { self.set(i); }, ranges[c.title], first.axis));
      });
    });
    function nearest(a) {
      var best = 0;
      angles.forEach(function (v, i) { if (Math.abs(v - a) < Math.abs(angles[best] - a)) best = i; });
      return best;
    }
    self.set = function (i) {
      i = ((Math.round(i) % n) + n) % n;
      self.index = i;
      slider.value = i;
      readout.textContent = first.axis ? first.axis.symbol + " = " + fmt(angles[i]) + " " + first.axis.unit
                                       : "φ = " + fmt(angles[i]) + "°";
      root.setAttribute("data-index", i);
      root.setAttribute("data-angle", angles[i]);
      drawings.forEach(function (d) { d.show(i); });
      curves.forEach(function (c) { c.show(i); });
    };
    self.play = function () {
      if (timer) return;
      play.textContent = "❚❚ pause";
      var last = null, acc = 0;
      function tick(t) {
        if (!timer) return;
        if (last !== null) {
          acc += (t - last) / 1000 * 60 * parseFloat(speed.value);  /* 60 positions per second at 1x */
          var step = Math.floor(acc);
          if (step > 0) { acc -= step; self.set(self.index + step); }
        }
        last = t;
        timer = window.requestAnimationFrame(tick);
      }
      timer = window.requestAnimationFrame(tick);
    };
    self.pause = function () {
      if (timer) window.cancelAnimationFrame(timer);
      timer = null;
      play.textContent = "▶ play";
    };
    play.addEventListener("click", function () { if (timer) self.pause(); else self.play(); });
    slider.addEventListener("input", function () { self.pause(); self.set(parseInt(slider.value, 10)); });
    /* the crank angle survives a re-load (machdyn watch): keyed by the view's place in the page */
    var key = order === undefined ? null : "machdyn:view:" + order, saved = null;
    try { saved = key && window.sessionStorage.getItem(key); } catch (e) { saved = null; }
    self.set(saved ? parseInt(saved, 10) : 0);
    if (key) window.addEventListener("pagehide", function () {
      try { window.sessionStorage.setItem(key, String(self.index)); } catch (e) { /* storage refused */ }
    });
  }

  /* ------------------------------------------------------------------ the design-space scatter */
  function SpaceView(root, data) {
    var self = this, cols = Object.keys(data.columns), W = 560, H = 380, L = 70, R = 16, T = 16, B = 44;
    self.root = root;
    var bar = html("div", { "class": "mdview-controls" }, root);
    function chooser(label, current) {
      html("span", {}, bar, label);
      var sel = html("select", { "class": "mdview-axis-" + label.charAt(0).toLowerCase() }, bar);
      cols.forEach(function (c) { var o = html("option", { value: c }, sel, c); if (c === current) o.selected = true; });
      sel.addEventListener("change", draw);
      return sel;
    }
    var sx = chooser("x:", data.x), sy = chooser("y:", data.y);
    var svg = el("svg", { viewBox: "0 0 " + W + " " + H, "class": "mdview-scatter" }, root);
    var tip = html("div", { "class": "mdview-tip" }, root);
    var detail = html("div", { "class": "mdview-detail" }, root);
    function numbers(i) {
      var t = html("table", { "class": "mdview-values" });
      html("tr", {}, t).appendChild(html("th", { colspan: 3 }, null,
        "Design " + (data.columns.design ? data.columns.design[i] : i) + " (" + data.status[i] + ")"));
      cols.forEach(function (c) {
        var tr = html("tr", {}, t);
        html("th", {}, tr, c); html("td", {}, tr, fmt(data.columns[c][i])); html("td", {}, tr, data.units[c] || "");
      });
      return t;
    }
    self.open = function (i) {
      detail.textContent = "";
      detail.setAttribute("data-design", i);
      detail.appendChild(numbers(i));
      var sc = data.scenes[String(i)];
      if (sc) {
        var holder = html("div", { "class": "mdview", id: root.id + "-d" + i }, detail);
        window.machdynViews.push(new MechanismView(holder, { scenes: { "": sc } }));
      } else {
        html("p", { "class": "caption" }, detail, "This design's motion is not stored in the report; write it " +
             "with its values as a problem file to see it move.");
      }
    };
    function draw() {
      svg.textContent = "";
      var xs = data.columns[sx.value], ys = data.columns[sy.value], reg = [];
      for (var i = 0; i < data.size; i++) {
        if (data.status[i] === "regular" && xs[i] !== null && ys[i] !== null) reg.push(i);
      }
      if (!reg.length) for (var k = 0; k < data.size; k++) if (xs[k] !== null && ys[k] !== null) reg.push(k);
      var x0 = Math.min.apply(null, reg.map(function (i) { return xs[i]; })), x1 = Math.max.apply(null, reg.map(function (i) { return xs[i]; }));
      var y0 = Math.min.apply(null, reg.map(function (i) { return ys[i]; })), y1 = Math.max.apply(null, reg.map(function (i) { return ys[i]; }));
      if (x1 === x0) { x0 -= 0.5; x1 += 0.5; }
      if (y1 === y0) { y0 -= 0.5; y1 += 0.5; }
      var mx = 0.04 * (x1 - x0), my = 0.04 * (y1 - y0);
      x0 -= mx; x1 += mx; y0 -= my; y1 += my;
      function px(v) { return L + (Math.min(Math.max(v, x0), x1) - x0) / (x1 - x0) * (W - L - R); }
      function py(v) { return T + (y1 - Math.min(Math.max(v, y0), y1)) / (y1 - y0) * (H - T - B); }
      el("rect", { x: L, y: T, width: W - L - R, height: H - T - B, "class": "mdview-frame" }, svg);
      [[x0, L, H - B + 14, "start"], [x1, W - R, H - B + 14, "end"]].forEach(function (t) {
        el("text", { x: t[1], y: t[2], "class": "mdview-tick", "text-anchor": t[3] }, svg).textContent = fmt(t[0]);
      });
      [[y0, H - B], [y1, T + 8]].forEach(function (t) {
        el("text", { x: L - 4, y: t[1], "class": "mdview-tick", "text-anchor": "end" }, svg).textContent = fmt(t[0]);
      });
      el("text", { x: (L + W - R) / 2, y: H - 8, "class": "mdview-label", "text-anchor": "middle" }, svg).textContent =
        sx.value + (data.units[sx.value] ? " [" + data.units[sx.value] + "]" : "");
      el("text", { x: 12, y: (T + H - B) / 2, "class": "mdview-label", "text-anchor": "middle",
                   transform: "rotate(-90 12 " + (T + H - B) / 2 + ")" }, svg).textContent =
        sy.value + (data.units[sy.value] ? " [" + data.units[sy.value] + "]" : "");
      if (data.front.length > 1) {
        var f = data.front.slice().sort(function (a, b) { return xs[a] - xs[b]; });
        el("polyline", { points: f.map(function (i) { return px(xs[i]) + "," + py(ys[i]); }).join(" "),
                         "class": "mdview-front" }, svg);
      }
      for (var j = 0; j < data.size; j++) {
        if (xs[j] === null || ys[j] === null) continue;
        var regular = data.status[j] === "regular";
        var dot = el("circle", { cx: px(xs[j]), cy: py(ys[j]), r: regular ? 3.2 : 2.4, "data-design": j,
                                 "class": "mdview-dot" + (regular ? "" : " mdview-irregular") }, svg);
        dot.addEventListener("mouseenter", hover(j));
        dot.addEventListener("mouseleave", function () { tip.style.display = "none"; });
        dot.addEventListener("click", (function (d) { return function () { self.open(d); }; })(j));
      }
      Object.keys(data.highlight).forEach(function (label) {
        var i = data.highlight[label];
        if (xs[i] === null || ys[i] === null) return;
        var g = el("g", { "class": "mdview-highlight", "data-highlight": label, "data-design": i }, svg);
        el("circle", { cx: px(xs[i]), cy: py(ys[i]), r: 7 }, g);
        el("text", { x: px(xs[i]) + 9, y: py(ys[i]) - 6 }, g).textContent = label;
        g.addEventListener("click", function () { self.open(i); });
      });
    }
    function hover(i) {
      return function (ev) {
        tip.textContent = "";
        tip.appendChild(numbers(i));
        tip.setAttribute("data-design", i);
        var box = root.getBoundingClientRect();
        tip.style.left = (ev.clientX - box.left + 12) + "px";
        tip.style.top = (ev.clientY - box.top + 12) + "px";
        tip.style.display = "block";
      };
    }
    draw();
    var first = Object.keys(data.highlight);
    if (first.length) self.open(data.highlight[first[0]]);
  }

  function start() {
    var nodes = document.querySelectorAll("div.mdview[data-view]");
    Array.prototype.forEach.call(nodes, function (root, order) {
      if (root.getAttribute("data-ready")) return;
      var data = JSON.parse(root.querySelector("script.mdview-data").textContent);
      var view = root.getAttribute("data-view") === "space" ? new SpaceView(root, data)
        : new MechanismView(root, data, order);
      root.setAttribute("data-ready", "1");
      window.machdynViews.push(view);
    });
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start); else start();
})();
