// The interactive page (geomcad/render/html.py): every number below was computed by geomcad;
// the script only shows frame k of them.
"use strict";
(function () {
  const D = JSON.parse(document.getElementById("frames").textContent);
  const N = D.n;
  const $ = (id) => document.getElementById(id);
  const slider = $("frame"), phiOut = $("phi"), play = $("play"), speed = $("speed");
  const HEAD = 3.0, HALF = 1.0;
  const r2 = (x) => Math.round(x * 100) / 100;

  function fmt(x) {
    if (x === 0 || Math.abs(x) < 1e-300) return "0";
    let s = Number(x.toPrecision(4)).toString();
    if (/e/.test(s)) s = x.toPrecision(4);
    if (D.lang === "ru") s = s.replace(".", ",");
    return s.replace("-", "\u2212");
  }
  const at = (arr, k) => [arr[2 * k], arr[2 * k + 1]];

  function setLine(el, a, b) {
    el.setAttribute("x1", a[0]); el.setAttribute("y1", a[1]);
    el.setAttribute("x2", b[0]); el.setAttribute("y2", b[1]);
  }
  function arrow(g, a, b) {
    const line = g.firstChild, head = g.lastChild;
    const dx = b[0] - a[0], dy = b[1] - a[1], len = Math.hypot(dx, dy);
    setLine(line, a, b);
    if (len <= HEAD) { head.setAttribute("points", ""); return; }
    const ux = dx / len, uy = dy / len, bx = b[0] - ux * HEAD, by = b[1] - uy * HEAD;
    head.setAttribute("points", `${r2(b[0])},${r2(b[1])} ${r2(bx - uy * HALF)},${r2(by + ux * HALF)} ` +
      `${r2(bx + uy * HALF)},${r2(by - ux * HALF)}`);
  }

  // the mechanism
  const M = D.mech;
  const links = M.links.map((_, i) => $("m-link-" + i));
  const joints = M.joints.map((p) => [p, $("m-j-" + p)]);
  const labels = M.labels.map((p) => [p, $("m-l-" + p)]);
  const blocks = Object.keys(M.sliders).map((p) => [p, $("m-slider-" + p)]);
  // the plans
  const plans = D.plans.map((P, i) => ({
    P,
    vectors: P.vectors.map((_, j) => $(`p${i}-v${j}`)),
    dots: Object.keys(P.points).map((n) => [n, $(`p${i}-d-${n}`), $(`p${i}-l-${n}`)]),
  }));
  const cursors = D.diagrams.map((_, i) => [$(`d${i}-c`), $(`d${i}-d`)]);
  const cells = D.table.map((_, j) => $("t-" + j));
  const stops = Array.from(document.querySelectorAll(".stop"));

  function show(k) {
    k = ((k % N) + N) % N;
    const pt = (p) => at(M.points[p], k);
    links.forEach((el, i) => el.setAttribute("points", M.links[i].map((p) => pt(p).join(",")).join(" ")));
    for (const [p, el] of joints) { const q = pt(p); el.setAttribute("cx", q[0]); el.setAttribute("cy", q[1]); }
    for (const [p, el] of blocks) {
      const q = pt(p);
      el.setAttribute("transform", `translate(${q[0]},${q[1]}) rotate(${-M.sliders[p][k]})`);
    }
    for (const [p, el] of labels) {
      const q = pt(p), up = p in M.sliders ? 4.2 : 2.0;
      el.setAttribute("x", r2(q[0] + 2.0)); el.setAttribute("y", r2(q[1] - up));
    }
    for (const { P, vectors, dots } of plans) {
      const pp = (n) => (n in P.points ? at(P.points[n], k) : P.pole);
      vectors.forEach((g, j) => arrow(g, pp(P.vectors[j][0]), pp(P.vectors[j][1])));
      for (const [n, dot, label] of dots) {
        const q = pp(n);
        dot.setAttribute("cx", q[0]); dot.setAttribute("cy", q[1]);
        label.setAttribute("x", r2(q[0] + 1.5)); label.setAttribute("y", r2(q[1] - 1.5));
      }
    }
    cursors.forEach(([line, dot], i) => {
      const q = at(D.diagrams[i], k);
      line.setAttribute("x1", q[0]); line.setAttribute("x2", q[0]);
      dot.setAttribute("cx", q[0]); dot.setAttribute("cy", q[1]);
    });
    cells.forEach((td, j) => {
      const v = D.table[j].values[k];
      td.textContent = fmt(v);
      td.dataset.value = String(v);
    });
    const phi = fmt(D.phi[k]);
    phiOut.value = phi;
    phiOut.textContent = phi;
    slider.value = String(k);
    slider.setAttribute("aria-valuetext", `φ1 = ${phi}°`);
    stops.forEach((b) => b.classList.toggle("at", Number(b.dataset.frame) === k));
    document.body.dataset.frame = String(k);
  }

  // playing
  let playing = false, last = 0, pos = 0;
  function tick(t) {
    if (!playing) return;
    if (last) pos = (pos + ((t - last) / 1000) * (N / D.period) * Number(speed.value)) % N;
    last = t;
    show(Math.floor(pos));
    requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    playing = on;
    play.textContent = on ? D.words.pause : D.words.play;
    play.setAttribute("aria-pressed", on ? "true" : "false");
    if (on) { pos = Number(slider.value); last = 0; requestAnimationFrame(tick); }
  }
  function go(k) { setPlaying(false); show(k); }
  function stop(dir) {
    const k = Number(slider.value);
    const ks = stops.map((b) => Number(b.dataset.frame)).sort((a, b) => a - b);
    if (!ks.length) return;
    const next = dir > 0 ? ks.find((x) => x > k) ?? ks[0] : [...ks].reverse().find((x) => x < k) ?? ks[ks.length - 1];
    go(next);
  }
  play.addEventListener("click", () => setPlaying(!playing));
  slider.addEventListener("input", () => go(Number(slider.value)));
  stops.forEach((b) => b.addEventListener("click", () => go(Number(b.dataset.frame))));
  document.addEventListener("keydown", (e) => {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const tag = e.target && e.target.tagName;
    if (tag === "SELECT" || (tag === "BUTTON" && (e.key === " " || e.key === "Enter"))) return;
    if ($("panel-motion").hidden) return;
    // the same steps on the slider and elsewhere (a range input's own Page Up is 10 % of it)
    const k = Number(slider.value);
    const step = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: 10, PageDown: -10 }[e.key];
    if (step !== undefined) { e.preventDefault(); go(k + step); return; }
    if (e.key === "Home") { e.preventDefault(); go(0); }
    else if (e.key === "End") { e.preventDefault(); go(N - 1); }
    else if (e.key === " ") { e.preventDefault(); setPlaying(!playing); }
    else if (e.key === "]") { e.preventDefault(); stop(1); }
    else if (e.key === "[") { e.preventDefault(); stop(-1); }
    else if (e.key === "+" || e.key === "=" || e.key === "-") {
      e.preventDefault();
      const i = speed.selectedIndex + (e.key === "-" ? -1 : 1);
      speed.selectedIndex = Math.max(0, Math.min(speed.options.length - 1, i));
    }
  });

  // tabs
  const tabs = Array.from(document.querySelectorAll('[role="tab"]'));
  function select(tab) {
    for (const t of tabs) {
      const on = t === tab;
      t.setAttribute("aria-selected", on ? "true" : "false");
      t.tabIndex = on ? 0 : -1;
      $(t.getAttribute("aria-controls")).hidden = !on;
    }
    if (tab.id !== "tab-motion") setPlaying(false);
  }
  tabs.forEach((t, i) => {
    t.tabIndex = i === 0 ? 0 : -1;
    t.addEventListener("click", () => select(t));
    t.addEventListener("keydown", (e) => {
      const d = { ArrowRight: 1, ArrowLeft: -1 }[e.key];
      if (d === undefined) return;
      e.preventDefault(); e.stopPropagation();
      const next = tabs[(i + d + tabs.length) % tabs.length];
      select(next); next.focus();
    });
  });
  show(0);
})();
