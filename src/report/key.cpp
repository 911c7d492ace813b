#include "report/key.hpp"

#include <algorithm>
#include <map>
#include <random>

#include <nlohmann/json.hpp>

#include "expr/print.hpp"
#include "report/tex.hpp"

namespace tackle {

using namespace GiNaC;

std::vector<std::vector<Variant>> draw_variants(const std::vector<std::pair<const Analysis*, const Derivation*>>& parts, int count,
                                                unsigned long long seed, int digits) {
  // The ranged parameters of all parts, by name, in the order they first appear (a phase's
  // shared parameters come first in each, so the same draw serves every phase).
  std::vector<const SymbolInfo*> ranged;
  for (const auto& [a, d] : parts)
    for (const auto& s : a->model.symbols->all())
      if (s->role == SymbolRole::parameter && s->range &&
          std::none_of(ranged.begin(), ranged.end(), [&](const SymbolInfo* r) { return r->name == s->name; }))
        ranged.push_back(s.get());
  std::vector<std::vector<Variant>> out(parts.size());
  if (ranged.empty() || count <= 0 || parts.empty()) return out;
  std::mt19937_64 rng(seed);
  // Each condition's normal form once; each draw only substitutes into it.
  std::vector<std::vector<NormalForm>> condition_forms(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (const auto& c : parts[p].second->conditions) condition_forms[p].emplace_back(c.simplified);
  int attempts = 0, drawn = 0;
  while (drawn < count) {
    if (++attempts > 1000 * count)
      throw InputError({{{parts[0].first->model.file, 0, 0},
                         "could not draw " + std::to_string(count) +
                             " variants that keep every validity condition (check the parameters' 'range')"}});
    std::map<std::string, ex> drawn_si;
    std::vector<Quantity> parameters;
    for (const SymbolInfo* s : ranged) {
      const auto [low, high] = *s->range;
      // A multiple of the step from `low`: k in [0, steps], steps = floor((high - low)/step).
      const numeric step = s->step ? *s->step : (high - low) / 100;
      const auto steps = static_cast<unsigned long long>(((high - low) / step).to_double() + 1e-9);
      const numeric value = low + numeric(static_cast<long>(rng() % (steps + 1))) * step;
      drawn_si[s->name] = value * s->unit_to_si;
      parameters.push_back({s->name, decimal_string(value, digits), s->unit, value.to_double()});
    }
    // Every condition of every part must hold and every answer must have a value (a draw
    // where one is undefined is drawn again).
    bool valid = true;
    std::vector<Variant> variants(parts.size());
    for (std::size_t p = 0; p < parts.size() && valid; ++p) {
      const SymbolTable& table = *parts[p].first->model.symbols;
      const Derivation& d = *parts[p].second;
      exmap values = table.values();
      Variant& v = variants[p];
      v.index = drawn + 1;
      for (const auto& s : table.all())
        if (auto it = drawn_si.find(s->name); it != drawn_si.end() && s->role == SymbolRole::parameter) values[s->sym] = it->second;
      for (const SymbolInfo* r : ranged)
        for (const auto& q : parameters)
          if (q.name == r->name && table.find(r->name)) v.parameters.push_back(q);
      for (const auto& s : table.all())
        if (s->definition)
          if (auto x = value_at(*s->definition, values)) values[s->sym] = *x;
      for (std::size_t k = 0; k < d.conditions.size(); ++k) {
        const auto& c = d.conditions[k];
        const auto exact = condition_forms[p][k].at(values);
        const ex x = exact ? evalf(*exact) : ex(0);
        valid = valid && exact && is_a<numeric>(x) && ex_to<numeric>(x).is_real() && relation_holds(ex_to<numeric>(x), c.op);
      }
      for (const auto& ans : d.answers) {
        if (!valid || !ans.closed_form) continue;
        const SymbolInfo* info = table.find(ans.symbol);
        auto value = evaluate_with(*ans.closed_form, values, info ? info->dimension : std::nullopt, digits, ans.unit);
        if (!value) {
          valid = false;
          continue;
        }
        v.answers.push_back({ans.name, value->decimal, value->unit, value->approx});
      }
    }
    if (!valid) continue;
    ++drawn;
    for (std::size_t p = 0; p < parts.size(); ++p)
      if (!variants[p].parameters.empty()) out[p].push_back(std::move(variants[p]));
  }
  return out;
}

std::vector<Variant> draw_variants(const Analysis& a, const Derivation& d, int count, unsigned long long seed, int digits) {
  return draw_variants({{&a, &d}}, count, seed, digits).front();
}

std::string write_key(const std::vector<KeyEntry>& entries, Format f) {
  if (f == Format::json) {
    nlohmann::ordered_json j;
    j["version"] = 1;
    j["problems"] = nlohmann::ordered_json::array();
    for (const auto& e : entries) {
      const Derivation& d = *e.derivation;
      nlohmann::ordered_json p;
      p["title"] = d.title;
      p["file"] = d.file;
      p["status"] = d.status;
      p["answers"] = nlohmann::ordered_json::array();
      for (const auto& a : d.answers) {
        nlohmann::ordered_json x{{"name", a.name}};
        if (a.closed_form) {
          x["closed_form"] = to_text(*a.closed_form);
          x["latex"] = to_latex(*a.closed_form);
        } else if (a.general) {
          x["general"] = to_text(*a.general);
        }
        if (a.value) {
          x["value"] = a.value->approx;
          x["decimal"] = a.value->decimal;
          x["unit"] = a.value->unit;
        }
        p["answers"].push_back(x);
      }
      p["variants"] = nlohmann::ordered_json::array();
      if (e.variants_asked && e.variants.empty()) p["no_variants"] = "no parameter of this problem has a 'range'";
      for (const auto& v : e.variants) {
        nlohmann::ordered_json x{{"index", v.index}};
        // Numbers as JSON numbers, like the answers above; `decimal` as printed in the key.
        for (const auto& q : v.parameters)
          x["parameters"][q.name] = {{"value", q.value}, {"decimal", q.number}, {"unit", q.unit}};
        for (const auto& q : v.answers) x["answers"][q.name] = {{"value", q.value}, {"decimal", q.number}, {"unit", q.unit}};
        p["variants"].push_back(x);
      }
      j["problems"].push_back(p);
    }
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  }
  const bool latex = f == Format::latex;
  std::string out;
  if (latex)
    out += "\\documentclass[11pt]{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n\\usepackage{amsmath}\n"
           "\\usepackage[margin=2cm]{geometry}\n\\begin{document}\n\\section*{Answer key}\n";
  else
    out += "# Answer key\n";
  for (const auto& e : entries) {
    const Derivation& d = *e.derivation;
    std::vector<std::string> asked;
    for (const auto& a : d.answers) asked.push_back(latex ? "$" + to_latex(a.symbol) + "$" : "$" + to_latex(a.symbol) + "$");
    if (latex) {
      out += "\\subsection*{" + tex_escape(d.title) + "}\nFind " + join(asked) + ".\n";
      for (const auto& a : d.answers) {
        if (a.closed_form) {
          out += "\\begin{equation*}\n  " + to_latex(a.symbol) + " = " + to_latex(*a.closed_form);
          if (a.value) out += " = " + a.value->decimal + (a.value->unit.empty() ? "" : "\\," + unit_latex(a.value->unit));
          out += "\n\\end{equation*}\n";
        } else if (a.general) {
          out += "\\begin{equation*}\n  " + to_latex(a.symbol) + " = " + to_latex(*a.general) +
                 " \\quad\\text{(not determined alone)}\n\\end{equation*}\n";
        }
      }
    } else {
      out += "\n## " + d.title + "\n\nFind " + join(asked) + ".\n\n";
      for (const auto& a : d.answers) {
        if (a.closed_form) {
          out += "- $" + to_latex(a.symbol) + " = " + to_latex(*a.closed_form) + "$";
          if (a.value) out += " = " + a.value->decimal + (a.value->unit.empty() ? "" : " " + a.value->unit);
          out += "\n";
        } else if (a.general) {
          out += "- $" + to_latex(a.symbol) + " = " + to_latex(*a.general) + "$ (not determined alone)\n";
        }
      }
    }
    if (e.variants.empty()) {
      // Asked for, but nothing to draw from: said, not silently left out.
      if (e.variants_asked)
        out += latex ? "\\par\\medskip\\noindent No variants: no parameter of this problem has a \\texttt{range}.\n"
                     : "\nNo variants: no parameter of this problem has a `range`.\n";
      continue;
    }
    // A table: the drawn parameters, then the answers.
    std::vector<std::string> head{"#"};
    for (const auto& q : e.variants.front().parameters) head.push_back(q.name);
    for (const auto& q : e.variants.front().answers) head.push_back(q.name);
    auto tex_cell = [](const Quantity& q) {
      return "$" + q.number + (q.unit.empty() ? "" : "\\," + unit_latex(q.unit)) + "$";
    };
    if (latex) {
      out += "\\par\\medskip\\noindent Variants:\\par\\smallskip\\noindent\n\\begin{tabular}{" +
             std::string(head.size(), 'l') + "}\n";
      std::vector<std::string> cells;
      // Each name typeset as in the derivation ($\\ddot{x}_{A}$, not ddot(x_A)).
      std::map<std::string, std::string> tex;
      for (const auto& p : d.parameters) tex[p.name] = p.tex;
      for (const auto& a : d.answers) tex[a.name] = a.tex;
      for (const auto& h : head)
        cells.push_back(h == "#" ? "\\#" : tex.count(h) && !tex[h].empty() ? "$" + tex[h] + "$" : "\\texttt{" + tex_escape(h) + "}");
      out += join(cells, " & ") + " \\\\\n\\hline\n";
      for (const auto& v : e.variants) {
        cells = {std::to_string(v.index)};
        for (const auto& q : v.parameters) cells.push_back(tex_cell(q));
        for (const auto& q : v.answers) cells.push_back(tex_cell(q));
        out += join(cells, " & ") + " \\\\\n";
      }
      out += "\\end{tabular}\n";
    } else {
      out += "\nVariants:\n\n| " + join(head, " | ") + " |\n|";
      for (std::size_t i = 0; i < head.size(); ++i) out += "---|";
      out += "\n";
      for (const auto& v : e.variants) {
        std::vector<std::string> cells{std::to_string(v.index)};
        for (const auto& q : v.parameters) cells.push_back(q.text());
        for (const auto& q : v.answers) cells.push_back(q.text());
        out += "| " + join(cells, " | ") + " |\n";
      }
    }
  }
  if (latex) out += "\\end{document}\n";
  return out;
}

}  // namespace tackle
