// What checks settled about answers' expressions, remembered (see check.hpp).
#include "check/check.hpp"

namespace tackle {

std::optional<SettledAnswers::Entry> SettledAnswers::find(const std::string& unknown, const GiNaC::ex& e) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto of = by_unknown_.find(unknown);
  if (of == by_unknown_.end()) return std::nullopt;
  const auto it = of->second.find(e);
  if (it == of->second.end()) return std::nullopt;
  return it->second;
}

void SettledAnswers::keep(const std::string& unknown, const GiNaC::ex& e, const Entry& entry) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (size_ >= capacity) {
    by_unknown_.clear();
    size_ = 0;
  }
  if (by_unknown_[unknown].emplace(e, entry).second) ++size_;
}

std::string SettledAnswers::simplest(const std::string& unknown, const GiNaC::ex& e,
                                     const std::function<std::string()>& make) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto of = by_unknown_.find(unknown);
    if (of != by_unknown_.end())
      if (const auto it = of->second.find(e); it != of->second.end() && it->second.simplest)
        return *it->second.simplest;
  }
  std::string made = make();  // (outside the lock: it may take long)
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto of = by_unknown_.find(unknown);
  if (of != by_unknown_.end())
    if (const auto it = of->second.find(e); it != of->second.end()) it->second.simplest = made;
  return made;
}

}  // namespace tackle
