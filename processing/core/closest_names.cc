#include "processing/core/closest_names.h"

#include <algorithm>
#include <cctype>
#include <utility>

namespace mocapfill {

namespace {

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

int EditDistance(std::string_view a, std::string_view b) {
  const std::string x = Lower(a), y = Lower(b);
  std::vector<int> row(y.size() + 1);
  for (size_t j = 0; j <= y.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= x.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= y.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (x[i - 1] == y[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[y.size()];
}

std::vector<std::string> ClosestNames(std::string_view name, const std::vector<std::string>& candidates, int count) {
  std::vector<std::pair<int, std::string>> scored;
  for (const std::string& c : candidates) scored.emplace_back(EditDistance(name, c), c);
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (size_t i = 0; i < scored.size() && static_cast<int>(i) < count; ++i) out.push_back(scored[i].second);
  return out;
}

std::string QuotedClosestNames(std::string_view name, const std::vector<std::string>& candidates, int count) {
  std::string out;
  for (const std::string& c : ClosestNames(name, candidates, count)) out += (out.empty() ? "'" : ", '") + c + "'";
  return out;
}

}  // namespace mocapfill
