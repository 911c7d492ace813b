// A fast test of an expression's class. GiNaC's is_a<T> is a dynamic_cast, which across
// shared-library boundaries compares type names with strcmp; on the printing and evaluation
// hot paths that dominated the time of a check. GiNaC's registered classes carry a static
// class-info object, so comparing its address answers the same question (possymbol and
// realsymbol share symbol's).
#pragma once

#include <ginac/ginac.h>

namespace tackle {

template <class T>
inline bool is_exactly(const GiNaC::ex& e) {
  return &GiNaC::ex_to<GiNaC::basic>(e).get_class_info() == &T::get_class_info_static();
}

}  // namespace tackle
