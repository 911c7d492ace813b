#include "report/step_page.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <stdexcept>

#include "expr/print.hpp"
#include "model/kinematics.hpp"
#include "report/html.hpp"
#include "report/sheet.hpp"

namespace tackle {

namespace {

// The form's look: steps as cards, each with its verdict's colour at the left.
const char* const page_style = R"css(<style>
.tryit{font-family:system-ui,"DejaVu Sans",sans-serif;font-size:.95em}
.tryit h2{font-family:"Latin Modern Roman","CMU Serif",Georgia,serif}
.names code{background:#f3f3f3;padding:0 .25em;border-radius:3px}
ol.steps{list-style:none;padding:0;margin:1em 0;counter-reset:step}
li.step{counter-increment:step;border:1px solid #ccc;border-left:6px solid #bbb;border-radius:4px;padding:.5em .8em;margin:.6em 0;background:#fff}
li.step[data-verdict=correct]{border-left-color:#2e7d32}li.step[data-verdict=incorrect]{border-left-color:#c62828}
li.step[data-verdict=invalid]{border-left-color:#ef6c00}li.step[data-verdict=undecided],li.step[data-verdict=unreachable]{border-left-color:#757575}
.step .head{display:flex;align-items:center;gap:.6em;margin-bottom:.35em}
.step .head .kind::before{content:"Step " counter(step) ": ";font-weight:600}
.step .head .kind{flex:1;color:#333}
.step .fields{display:flex;flex-wrap:wrap;align-items:center;gap:.5em}
.step input.text{flex:1;min-width:16em;font-family:"DejaVu Sans Mono",monospace;font-size:1em;padding:.3em .4em}
.step select,.step input{font-size:1em;padding:.25em}
.step .fields.diagram{display:block}
.step .echo{margin:.4em 0 0 .2em;min-height:1.2em}
.verdict{margin-top:.3em}.badge{display:inline-block;min-width:6em;text-align:center;border-radius:3px;padding:0 .4em;color:#fff;background:#757575;font-weight:600}
.badge[data-verdict=correct]{background:#2e7d32}.badge[data-verdict=incorrect]{background:#c62828}.badge[data-verdict=invalid]{background:#ef6c00}
.verdict ul{margin:.3em 0 0 1.2em;padding:0}
table.forces{border-collapse:collapse;margin:.3em 0}table.forces th,table.forces td{padding:.15em .4em;text-align:left;border-bottom:1px solid #eee}
table.forces input.name{width:6em}table.forces input.dir{width:8em}
.buttons{display:flex;flex-wrap:wrap;gap:.5em;margin:.6em 0}
button{font-size:.95em;padding:.3em .8em;border:1px solid #888;border-radius:4px;background:#f7f7f7;cursor:pointer}
button.grade{background:#1565c0;color:#fff;border-color:#1565c0;font-weight:600}button.remove{font-size:.85em;padding:.1em .5em}
#grade{margin-top:1em}#grade .score{font-size:1.2em;font-weight:600}
#grade table{border-collapse:collapse}#grade td,#grade th{padding:.15em .6em;border-bottom:1px solid #ddd;text-align:left}
.notice{color:#555;font-size:.9em}
</style>
)css";

// The form's behaviour. Student text only ever reaches the page as textContent or an input's
// value; the echoed LaTeX (tackle's reading of the step) is typeset by KaTeX (trust off).
const char* const page_script = R"js(<script>
"use strict";
document.addEventListener("DOMContentLoaded", function () {
  const P = JSON.parse(document.getElementById("tackle-problem").textContent);
  const base = P.endpoint ? P.endpoint.replace(/\/+$/, "") + "/" : "";
  const list = document.getElementById("steps");
  const gradeBox = document.getElementById("grade");
  const kindName = {equation: "equation", answer: "final answer", fbd: "free body diagram"};

  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === "class") e.className = v; else e.setAttribute(k, v);
    }
    for (const c of children) if (c !== null && c !== undefined) e.append(c);
    return e;
  }
  function option(value, label, selected) {
    const o = el("option", {value: value}, label);
    if (selected) o.selected = true;
    return o;
  }
  function typeset(target, tex) {
    target.textContent = "";
    if (!tex) return;
    try { katex.render(tex, target, {throwOnError: false, displayMode: false}); } catch (e) { target.textContent = tex; }
  }
  async function post(path, body) {
    const r = await fetch(base + path, {method: "POST", headers: {"Content-Type": "application/json"}, body: JSON.stringify(body)});
    let data = null;
    try { data = await r.json(); } catch (e) { data = null; }
    if (!r.ok) throw new Error(data && data.error ? data.error : "the checker answered " + r.status);
    if (!data || typeof data !== "object") throw new Error("the checker's answer is not JSON");
    return data;
  }

  // A free body diagram's rows: name, point, direction.
  function directionField(value) {
    if (P.dims === 1) {
      const s = el("select", {class: "dir", "aria-label": "direction"});
      s.append(option("+1", "+" + P.axes[0], value === "+1"), option("-1", "\u2212" + P.axes[0], value === "-1"), option("any", "any", value === "any"));
      return s;
    }
    const placeholder = P.dims === 2 ? "degrees, or any" : "x, y, z, or any";
    const i = el("input", {class: "dir", type: "text", placeholder: placeholder, "aria-label": "direction"});
    i.value = value || "";
    return i;
  }
  function pointField(value) {
    const s = el("select", {class: "at", "aria-label": "point"});
    s.append(option("", "(not said)", !value));
    // A body's name is its center of mass (among the points, or after them).
    for (const p of P.points) s.append(option(p, P.bodies.includes(p) ? p + " (center of mass)" : p, value === p));
    for (const b of P.bodies) if (!P.points.includes(b)) s.append(option(b, b + " (center of mass)", value === b));
    return s;
  }
  function forceRow(row, f) {
    const tr = el("tr", {class: "force"});
    const name = el("input", {class: "name", type: "text", placeholder: P.hints.force, "aria-label": "force's name"});
    name.value = f.name || "";
    const remove = el("button", {type: "button", class: "remove"}, "\u00d7");
    remove.addEventListener("click", function () { tr.remove(); changed(row); });
    const kind = el("select", {class: "kind", "aria-label": "kind of force"});
    kind.append(option("", "(not said)", !f.kind));
    for (const k of ["weight", "tension", "spring", "damper", "applied", "support"]) kind.append(option(k, k, f.kind === k));
    tr.append(el("td", {}, name), el("td", {}, pointField(f.at || "")), el("td", {}, directionField(f.dir || "")), el("td", {}, kind),
              el("td", {}, remove));
    for (const input of tr.querySelectorAll("input, select")) input.addEventListener("input", function () { changed(row); });
    return tr;
  }
  function direction(text) {
    const t = text.trim();
    if (t === "any") return {direction: "any"};
    if (P.dims === 1) return {direction: [Number(t)]};
    if (P.dims === 2 && t !== "" && !t.includes(",")) return {angle: Number(t)};
    return {direction: t.split(/[\s,]+/).filter(function (s) { return s !== ""; }).map(Number)};
  }

  // A step's data, as the checker reads it (null: nothing written yet).
  function stepData(row) {
    const kind = row.dataset.kind;
    if (kind === "equation") {
      const text = row.querySelector("input.text").value;
      return text.trim() ? {kind: kind, equation: text} : null;
    }
    if (kind === "answer") {
      const text = row.querySelector("input.text").value;
      return text.trim() ? {kind: kind, unknown: row.querySelector("select.unknown").value, answer: text} : null;
    }
    const forces = [];
    for (const tr of row.querySelectorAll("tr.force")) {
      const f = {name: tr.querySelector("input.name").value};
      const at = tr.querySelector("select.at").value;
      if (at) f.at = at;
      const kind = tr.querySelector("select.kind").value;
      if (kind) f.kind = kind;
      Object.assign(f, direction(tr.querySelector(".dir").value));
      forces.push(f);
    }
    return {kind: kind, fbd: {body: row.querySelector("select.body").value, forces: forces}};
  }

  function showVerdict(row, r) {
    row.setAttribute("data-verdict", r.verdict);
    const box = row.querySelector(".verdict");
    box.textContent = "";
    box.append(el("span", {class: "badge", "data-verdict": r.verdict}, r.verdict), " ", el("span", {class: "summary"}, r.summary || ""));
    const more = [];
    // (what a correct equation is or follows from, its summary says; a diagram's forces, here)
    for (const f of r.forces || []) more.push(f.phrase + ": " + f.status.replace(/_/g, " ") + (f.drawn_as && f.drawn_as.length ? " (your " + f.drawn_as.join(", ") + ")" : ""));
    for (const x of r.extras || []) more.push(x.message);
    if (more.length) {
      const ul = el("ul");
      for (const m of more) ul.append(el("li", {}, m));
      box.append(ul);
    }
    typeset(row.querySelector(".echo"), r.latex || "");
  }

  async function check(row) {
    const data = stepData(row);
    const seq = (row.seq = (row.seq || 0) + 1);
    if (!data) {
      row.removeAttribute("data-verdict");
      row.querySelector(".verdict").textContent = "";
      row.querySelector(".echo").textContent = "";
      return;
    }
    let r;
    try {
      r = await post("step", data);
    } catch (e) {
      r = {verdict: "unreachable", summary: "could not check this step: " + e.message};
    }
    if (seq === row.seq) showVerdict(row, r);
  }
  function changed(row) {
    clearTimeout(row.timer);
    row.timer = setTimeout(function () { check(row); }, 300);
  }

  function addStep(kind, init) {
    init = init || {};
    const row = el("li", {class: "step", "data-kind": kind});
    const remove = el("button", {type: "button", class: "remove"}, "Remove");
    remove.addEventListener("click", function () { row.remove(); });
    row.append(el("div", {class: "head"}, el("span", {class: "kind"}, kindName[kind]), remove));
    const fields = el("div", {class: "fields"});
    if (kind === "equation" || kind === "answer") {
      const input = el("input", {class: "text", type: "text", spellcheck: "false", autocomplete: "off",
                                 placeholder: kind === "equation" ? P.hints.equation : "", "aria-label": kindName[kind]});
      if (kind === "answer") {
        // The hint: the problem's own parameters, or a number in the chosen unknown's unit.
        const s = el("select", {class: "unknown", "aria-label": "unknown"});
        for (const u of P.unknowns) s.append(option(u.name, u.name, init.unknown === u.name));
        const hint = function () {
          const u = P.unknowns.find(function (x) { return x.name === s.value; });
          input.placeholder = P.hints.answer + (u && u.unit ? (P.hints.answer ? ", or " : "") + "a number in " + u.unit : "");
        };
        s.addEventListener("change", function () { hint(); changed(row); });
        hint();
        fields.append(s, " = ");
      }
      input.value = init.text || "";
      input.addEventListener("input", function () { changed(row); });
      fields.append(input);
    } else {
      const s = el("select", {class: "body", "aria-label": "body"});
      for (const b of P.bodies) s.append(option(b, b, init.body === b));
      s.addEventListener("change", function () { changed(row); });
      const table = el("table", {class: "forces"});
      table.append(el("tr", {}, el("th", {}, "force"), el("th", {}, "at"),
                       el("th", {}, P.dims === 1 ? "direction" : P.dims === 2 ? "direction (degrees from " + P.axes[0] + ")" : "direction"),
                       el("th", {}, "kind"), el("th")));
      for (const f of init.forces || [{}]) table.append(forceRow(row, f));
      const add = el("button", {type: "button"}, "Add a force");
      add.addEventListener("click", function () { table.append(forceRow(row, {})); });
      fields.classList.add("diagram");
      fields.append(el("label", {}, "Body ", s), table, el("div", {}, add));
    }
    row.append(fields, el("div", {class: "echo"}), el("div", {class: "verdict", "aria-live": "polite"}));
    list.append(row);
    return row;
  }

  async function gradeAll() {
    const steps = [];
    for (const row of list.querySelectorAll("li.step")) {
      const d = stepData(row);
      if (!d) continue;
      if (d.kind === "equation") steps.push({equation: d.equation});
      else if (d.kind === "answer") steps.push({answer: d.answer, unknown: d.unknown});
      else steps.push({fbd: d.fbd});
    }
    gradeBox.textContent = "";
    let g;
    try {
      g = await post("solution", {steps: steps});
    } catch (e) {
      gradeBox.setAttribute("data-score", "");
      gradeBox.append(el("p", {class: "notice"}, "Could not grade the solution: " + e.message));
      return;
    }
    if (g.verdict === "invalid") {
      gradeBox.setAttribute("data-score", "");
      gradeBox.append(el("p", {}, el("span", {class: "badge", "data-verdict": "invalid"}, "invalid"), " " + g.summary));
      return;
    }
    gradeBox.setAttribute("data-score", g.score + "/" + g.max_score);
    gradeBox.append(el("h2", {}, "Grade"), el("p", {class: "score"}, "Score: " + Number(g.score.toFixed(3)) + " of " + g.max_score));
    const ol = el("ol");
    for (const s of g.steps) ol.append(el("li", {}, el("span", {class: "badge", "data-verdict": s.verdict}, s.verdict), " " + (s.summary || "") + (s.note ? " (" + s.note + ")" : "")));
    if (g.steps.length) gradeBox.append(ol);
    if (g.first_wrong) gradeBox.append(el("p", {}, "First step that is not correct: " + g.first_wrong + "."));
    gradeBox.append(el("p", {}, "Used: " + (g.used.length ? g.used.join(", ") : "none") + "."),
                    el("p", {class: "missing"}, "Missing (needed for the unknowns asked): " + (g.missing.length ? g.missing.join(", ") : "none") + "."));
    const t = el("table", {}, el("tr", {}, el("th", {}, "part"), el("th", {}, "points"), el("th", {}, "done")));
    for (const p of g.parts) {
      if (p.graded) t.append(el("tr", {}, el("td", {}, p.name), el("td", {}, Number(p.score.toFixed(3)) + " of " + p.max_score), el("td", {}, p.done + " of " + p.of)));
      else t.append(el("tr", {class: "not-graded"}, el("td", {}, p.name), el("td", {}, "not graded"), el("td", {}, p.not_graded)));
    }
    if (g.wrong && g.penalty) t.append(el("tr", {class: "wrong-steps"}, el("td", {}, "wrong steps"), el("td", {}, "\u2212" + Number(g.penalty.toFixed(3))),
                                          el("td", {}, g.wrong + " incorrect")));
    gradeBox.append(t);
  }

  for (const [kind, label] of [["equation", "Add an equation"], ["answer", "Add a final answer"], ["fbd", "Add a free body diagram"]]) {
    const b = el("button", {type: "button"}, label);
    b.addEventListener("click", function () { addStep(kind).querySelector("input, select").focus(); });
    document.getElementById("add").append(b);
  }
  const gradeButton = el("button", {type: "button", class: "grade"}, "Grade the solution");
  gradeButton.addEventListener("click", gradeAll);
  document.getElementById("add").append(gradeButton);

  // Steps given in the address (?eq=...&ans=T:...&fbd={json}, or the same after #), checked now.
  const given = new URLSearchParams(location.search);
  if (location.hash.length > 1) for (const [k, v] of new URLSearchParams(location.hash.slice(1))) given.append(k, v);
  const first = [];
  for (const [k, v] of given) {
    if (k === "eq") first.push(addStep("equation", {text: v}));
    else if (k === "ans") {
      const colon = v.indexOf(":");
      first.push(addStep("answer", colon < 0 ? {text: v} : {unknown: v.slice(0, colon), text: v.slice(colon + 1)}));
    } else if (k === "fbd") {
      let f = null;
      try { f = JSON.parse(v); } catch (e) { f = null; }
      if (f && typeof f === "object") {
        const forces = [];
        for (const x of Array.isArray(f.forces) ? f.forces : []) {
          const dir = x.direction === "any" ? "any" : x.angle !== undefined ? String(x.angle)
                    : Array.isArray(x.direction) ? (P.dims === 1 ? (x.direction[0] < 0 ? "-1" : "+1") : x.direction.join(", ")) : "";
          forces.push({name: String(x.name || ""), at: String(x.at || ""), dir: dir, kind: String(x.kind || "")});
        }
        first.push(addStep("fbd", {body: String(f.body || ""), forces: forces}));
      }
    }
  }
  if (!first.length) addStep("equation");
  Promise.all(first.map(check)).then(function () {
    if (given.has("grade")) return gradeAll();
  }).then(function () { document.body.setAttribute("data-checked", "true"); });
});
</script>
)js";

// Where the page may connect: its own origin, and the endpoint's when that is elsewhere.
std::string connect_sources(const std::string& endpoint) {
  std::string out = "'self'";
  for (const char* scheme : {"http://", "https://"})
    if (endpoint.rfind(scheme, 0) == 0) {
      const std::size_t host = std::string(scheme).size(), slash = endpoint.find('/', host);
      out += " " + endpoint.substr(0, slash);
    }
  return out;
}

// The equation hint: the problem's first balance by its name, and its inertial side where that
// gives nothing away (nothing, or a body's mass times its coordinate's acceleration: what the
// forces add up to; the forces are the student's to find); else the first constraint's.
std::string equation_hint(const Derivation& d, const Model& m) {
  for (const Equation& e : d.equations) {
    if (e.kind != Equation::Kind::lmb && e.kind != Equation::Kind::amb) continue;
    bool plain = e.rhs.is_zero();
    if (e.bodies.size() == 1 && !e.system) {
      const Body& b = m.bodies[static_cast<std::size_t>(e.bodies.front())];
      const GiNaC::ex a = kinematics::acceleration_symbol(m, b);
      plain = plain || (GiNaC::is_a<GiNaC::symbol>(a) && (e.rhs - b.mass * a).expand().is_zero());
    }
    return e.label + ": ... = " + (plain ? to_text(e.rhs) : std::string("..."));
  }
  for (const Equation& e : d.equations)
    if (e.kind == Equation::Kind::constraint_acceleration) return e.label + ": ... = 0";
  return "";
}

// The hints the form shows, from the problem itself, never from another: its first balance
// (equation_hint), the parameters an answer is written in, the name of its first unknown force.
nlohmann::ordered_json hints(const Derivation& d, const Model& m) {
  nlohmann::ordered_json h{{"equation", equation_hint(d, m)}, {"answer", ""}, {"force", ""}};
  std::vector<std::string> names;
  for (const auto& p : d.parameters)
    if (p.kind == "parameter" || p.kind == "given") names.push_back(p.name);
  if (!names.empty())
    h["answer"] =
        "in " +
        join(std::vector<std::string>(
            names.begin(), names.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(names.size(), 4)))) +
        (names.size() > 4 ? ", ..." : "");
  for (const auto& u : d.unknowns) {
    const SymbolInfo* s = m.symbols ? m.symbols->find(u) : nullptr;
    if (s && s->dimension && *s->dimension == Dimension::force()) {
      h["force"] = s->name;
      break;
    }
  }
  return h;
}

}  // namespace

std::string endpoint_problem(const std::string& endpoint) {
  if (endpoint.size() > 2000) return "is longer than 2000 characters";
  for (char c : endpoint) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= ' ' || u >= 127 || std::string("\"'`;,<>\\?#").find(c) != std::string::npos)
      return std::string("has '") +
             (u <= ' ' || u >= 127 ? std::string("a space or control character") : std::string(1, c)) +
             "' (expected a path such as /tackle or an http(s) URL)";
  }
  // A scheme is what comes before a ':' that no '/' precedes (javascript:..., data:...).
  const std::size_t colon = endpoint.find(':');
  if (colon != std::string::npos && colon < endpoint.find('/') && endpoint.rfind("http://", 0) != 0 &&
      endpoint.rfind("https://", 0) != 0)
    return "is a URL that is not http or https";
  if ((endpoint == "http://" || endpoint == "https://")) return "has no host";
  return "";
}

std::string step_page(const Derivation& d, const Model& m, const std::string& endpoint) {
  if (const std::string problem = endpoint_problem(endpoint); !problem.empty())
    throw std::invalid_argument("the endpoint '" + endpoint + "' " + problem);
  nlohmann::ordered_json config;
  config["endpoint"] = endpoint;
  config["dims"] = m.dims();
  config["axes"] = m.axes;
  config["points"] = nlohmann::json::array();
  for (const auto& p : m.points) config["points"].push_back(p.name);
  config["bodies"] = nlohmann::json::array();
  for (const auto& b : m.bodies) config["bodies"].push_back(b.name);
  config["unknowns"] = nlohmann::json::array();
  for (const auto& a : d.answers)
    config["unknowns"].push_back({{"name", a.name}, {"tex", a.tex}, {"unit", a.value ? a.value->unit : ""}});
  config["hints"] = hints(d, m);
  // In a script element: no "</script>" (nor "<!--") can end it early.
  std::string json;
  for (char c : config.dump()) json += c == '<' ? std::string("\\u003c") : std::string(1, c);

  // The names a student types: the problem's parameters, unknowns and positions.
  std::vector<std::string> names;
  auto name_of = [&](const GiNaC::ex& e) {
    const SymbolInfo* s = m.symbols ? m.symbols->find(e) : nullptr;
    if (s && std::find(names.begin(), names.end(), s->name) == names.end()) names.push_back(s->name);
  };
  for (const auto& p : d.parameters)
    if ((p.kind == "parameter" || p.kind == "given") && std::find(names.begin(), names.end(), p.name) == names.end())
      names.push_back(p.name);
  for (const auto& u : d.unknowns) name_of(u);
  for (const auto& q : m.coordinates)
    if (q.kind == Coordinate::Kind::translation) name_of(q.q);
  std::string typed;
  for (const auto& n : names) typed += (typed.empty() ? "" : ", ") + std::string("<code>") + html_escape(n) + "</code>";

  std::string body = "<h1>" + html_escape(d.title) + "</h1>\n" + sheet_problem_html(SheetEntry{&d, &m, {}});
  body += "<div class=\"tryit\">\n<h2>Your solution</h2>\n";
  // What an equation may be: a constraint held constant only where the problem has one.
  const std::string equations = m.constraints.empty()
                                    ? "a balance"
                                    : "a balance, a quantity held constant (<code>... = const</code>, in the "
                                      "positions) or its derivatives";
  // Rates and accelerations, shown on the problem's own first coordinate.
  std::string rates;
  for (const auto& q : m.coordinates)  // (in body order, a body's position before its angle)
    if (const SymbolInfo* s = m.symbols ? m.symbols->find(q.q) : nullptr; s && rates.empty())
      rates = "; <code>dot(" + html_escape(s->name) + ")</code> and <code>ddot(" + html_escape(s->name) +
              ")</code> for its rate and acceleration";
  body += "<p class=\"names\">Write each step as you would on paper, one a line: an equation (" + equations +
          "), a final answer, or a free body diagram. Each is checked as you type. Names: " + typed + rates + ".</p>\n";
  body +=
      "<ol class=\"steps\" id=\"steps\"></ol>\n<div class=\"buttons\" id=\"add\"></div>\n<div id=\"grade\" "
      "aria-live=\"polite\"></div>\n";
  body +=
      "<p class=\"notice\">Checked by tackle; a verdict names what is wrong in words of physics and never shows the "
      "correct equation.</p>\n</div>\n";
  body += "<script type=\"application/json\" id=\"tackle-problem\">" + json + "</script>\n";

  const std::string policy =
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
      "style-src 'unsafe-inline'; font-src data:; img-src data:; connect-src " +
      html_escape(connect_sources(endpoint)) + "; base-uri 'none'; form-action 'none'\">\n";
  return html_page("Try it: " + d.title, body, policy + page_style + page_script);
}

}  // namespace tackle
