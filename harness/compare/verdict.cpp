#include "compare/verdict.h"

#include <algorithm>
#include <sstream>

namespace rayspec {
namespace {

int severity(Status s) {
  switch (s) {
    case Status::Pass:
      return 0;
    case Status::NotSupported:
      return 1;
    case Status::QualityWarning:
      return 2;
    case Status::CaseError:
      return 3;
    case Status::Fail:
      return 4;
    case Status::Timeout:
      return 5;
    case Status::Crash:
      return 6;
  }
  return 6;
}

}  // namespace

bool parseStatus(const std::string& name, Status* out) {
  const std::optional<Status> s = valueNamed<Status>(name);
  if (s) *out = *s;
  return s.has_value();
}

Status worse(Status a, Status b) {
  return severity(a) >= severity(b) ? a : b;
}

bool isFailing(Status s) {
  return severity(s) >= severity(Status::CaseError);
}

bool findingNames(const Finding& f, const std::string& rule) {
  return std::find(f.evidence.begin(), f.evidence.end(), rule) != f.evidence.end() ||
         labelNames(f, rule);
}

bool labelNames(const Finding& f, const std::string& rule) {
  for (size_t start = 0; start <= f.rule.size();) {
    const size_t end = std::min(f.rule.find('/', start), f.rule.size());
    if (f.rule.compare(start, end - start, rule) == 0) return true;
    start = end + 1;
  }
  return false;
}

void Verdict::add(Finding f) {
  status = worse(status, f.status);
  findings.push_back(std::move(f));
}

std::string findingLine(const Finding& f) {
  std::ostringstream s;
  s << statusName(f.status) << ": " << (f.rule.empty() ? "" : f.rule + ": ") << f.message;
  if (!f.rays.empty()) {
    s << " (" << f.ray_count << " rays; first:";
    for (uint32_t r : f.rays) s << ' ' << r;
    s << ')';
  }
  return s.str();
}

namespace {
constexpr size_t kHeadlineOthers = 6;  // findings named after the first, at most
}  // namespace

std::string Verdict::headline() const {
  const Finding* worst = nullptr;
  for (const Finding& f : findings)
    if (f.status == status && f.status != Status::Pass) {
      worst = &f;
      break;
    }
  if (!worst) return statusName(status);
  std::ostringstream s;
  s << findingLine(*worst);
  // Every other finding of the same status, with its ray count: a Fail in
  // three fields names all three.
  size_t also = 0;
  for (const Finding& f : findings) {
    if (&f == worst || f.status != status) continue;
    if (++also > kHeadlineOthers) continue;
    s << (also == 1 ? "; also " : "; ") << (f.rule.empty() ? "" : f.rule + ": ") << f.message;
    if (f.ray_count) s << " (" << f.ray_count << " rays)";
  }
  if (also > kHeadlineOthers) s << "; and " << also - kHeadlineOthers << " more";
  return s.str();
}

}  // namespace rayspec
