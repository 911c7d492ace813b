// The Python module's display in notebooks (Jupyter, issue 45): Problem._repr_html_ (the
// problem as the report's HTML writer writes it, a fragment whose math the notebook's MathJax
// typesets) and _repr_latex_ (its equations), and the Python half (display.py, compiled in):
// the checks' results, the answers and a variant as dicts and lists that show themselves, and
// Problem.derivation().
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "core/units.hpp"
#include "model/model.hpp"
#include "report/derivation.hpp"
#include "report/notebook.hpp"

namespace tackle::python {

namespace py = pybind11;

/// An id for one fragment: "tackle-" and random hex digits, so that outputs of several kernel
/// runs kept in one notebook do not share one.
[[nodiscard]] std::string fragment_id();
/// `view`: "problem", "derivation" or "answers" (ValueError otherwise).
[[nodiscard]] NotebookView notebook_view(const std::string& view);
/// Each parameter's and answer's name with its LaTeX ({"ddot(x_A)": "\\ddot{x}_{A}"}).
[[nodiscard]] py::dict names_latex(const Derivation& d);
/// Runs display.py in the module `m` (after Problem is defined).
void run_display_py(py::module_& m);

/// Adds the display to `m`'s class Problem, whose `derivation()` and `model()` give what it
/// shows.
template <class Problem>
void add_display(py::module_& m) {
  auto problem = py::reinterpret_borrow<py::class_<Problem>>(m.attr("Problem"));
  problem
      .def(
          "_repr_html_",
          [](const Problem& p) {
            return notebook_html(p.derivation(), p.model(), fragment_id(), NotebookView::problem);
          },
          "The problem as HTML for a notebook: title, statement, sketch, answers, and the derivation folded")
      .def(
          "_repr_latex_",
          [](const Problem& p) -> py::object {
            const std::string tex = notebook_latex(p.derivation(), true);
            return tex.empty() ? py::none() : py::object(py::str(tex));
          },
          "The derivation's equations as LaTeX (one align* block), or None without equations")
      .def(
          "_notebook_html",
          [](const Problem& p, const std::string& view) {
            return notebook_html(p.derivation(), p.model(), fragment_id(), notebook_view(view));
          },
          py::arg("view") = "problem")
      .def(
          "_notebook_latex", [](const Problem& p, bool full) { return notebook_latex(p.derivation(), full); },
          py::arg("full") = true)
      .def("_names_latex", [](const Problem& p) { return names_latex(p.derivation()); });
  m.def(
      "_unit_latex", [](const std::string& unit) { return unit_latex(unit); }, py::arg("unit"),
      "A unit as LaTeX (m/s^2: \\mathrm{m/s^{2}})");
  run_display_py(m);
}

}  // namespace tackle::python
