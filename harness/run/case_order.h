// The order cases are dealt to workers: longest first, by what each case took
// the last time it ran (kept in <cache dir>/case-seconds.json), cases never
// timed before all others, so that no long case starts last and leaves one
// worker running alone. Only the order of running changes: reports list the
// cases in their own order.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rayspec {

// name -> seconds; empty when the cache has none (or it does not read).
std::map<std::string, double> loadCaseSeconds(const std::string& cache_dir);
// Adds these timings to the cache's (best effort: a cache that cannot be
// written only loses the order of the next run).
void saveCaseSeconds(const std::string& cache_dir, const std::map<std::string, double>& seconds);

// Positions 0..names.size()-1, longest first; ties (and the untimed) in
// their own order.
std::vector<size_t> longestFirst(const std::vector<std::string>& names,
                                 const std::map<std::string, double>& seconds);

}  // namespace rayspec
