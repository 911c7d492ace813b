// Every memory a thread keeps, made in one place: the caches of pure functions of expressions
// (the printed text of an expression, its normal form, a sum's sign, a polynomial's factors)
// and the printer's state while it prints. thread_memory<Tag, T>() is this thread's T of kind
// Tag, made on first use (zero, or empty). What a cache remembers changes no output: equal
// keys give equal values, and each cache bounds itself (see remembered() in rational.hpp).
// `grep -rn thread_memory src` lists them all.
#pragma once

namespace tackle {

template <class Tag, class T>
T& thread_memory() {
  thread_local T memory{};
  return memory;
}

}  // namespace tackle
