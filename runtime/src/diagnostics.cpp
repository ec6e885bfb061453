#include "kestrel/runtime/diagnostics.hpp"

#include <algorithm>
#include <tuple>

namespace kestrel {

std::string Diagnostic::str() const {
  std::string prefix = where.str();
  if (!prefix.empty()) prefix += ": ";
  return prefix + (severity == Severity::error ? "error: " : "warning: ") + message;
}

// A part included twice is read twice: what is wrong in its file is said once.
void Diagnostics::add(Diagnostic::Severity severity, SourceLocation where, std::string message) {
  Diagnostic d{severity, std::move(where), std::move(message)};
  if (said_.insert(d.str()).second) items_.push_back(std::move(d));
}

void Diagnostics::error(SourceLocation where, std::string message) {
  add(Diagnostic::Severity::error, std::move(where), std::move(message));
}

void Diagnostics::warning(SourceLocation where, std::string message) {
  add(Diagnostic::Severity::warning, std::move(where), std::move(message));
}

void Diagnostics::append(const Diagnostics& other) {
  for (const Diagnostic& d : other.items_) add(d.severity, d.where, d.message);
}

bool Diagnostics::has_errors() const { return error_count() > 0; }

std::size_t Diagnostics::error_count() const {
  return static_cast<std::size_t>(std::count_if(
      items_.begin(), items_.end(), [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::error; }));
}

void Diagnostics::sort() {
  std::stable_sort(items_.begin(), items_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.where.file, a.where.line, a.where.column) < std::tie(b.where.file, b.where.line, b.where.column);
  });
}

std::string Diagnostics::str() const {
  std::string out;
  for (const auto& d : items_) out += d.str() + "\n";
  return out;
}

namespace {
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t substitution = diagonal + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}
}  // namespace

std::string nearest_name(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::string::npos;
  // A shortened name ("rate" for "rate_hz") is a likely slip even when many letters are missing.
  for (const auto& c : candidates) {
    if (word.size() >= 3 && c.size() > word.size() && c.compare(0, word.size(), word) == 0) return c;
  }
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  // A typo changes a few characters; beyond a third of the word it is a different name.
  const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
  return best_distance <= limit ? best : std::string();
}

}  // namespace kestrel
