#include "case/structure_queries.h"

#include <algorithm>

#include "case/case.h"

namespace rayspec {

bool StructureQueries::asks(StructureQuery q) const {
  return std::find(queries.begin(), queries.end(), q) != queries.end();
}

bool StructureQueries::needsMaintenance1() const {
  return asks(StructureQuery::Size) || asks(StructureQuery::BottomLevelPointers);
}

std::vector<std::set<uint32_t>> referencedBlases(const Scene& scene) {
  std::vector<std::set<uint32_t>> levels(scene.tlasCount());
  for (const Instance& i : scene.instances)
    if (i.blas) levels[i.tlas].insert(*i.blas);
  return levels;
}

}  // namespace rayspec
