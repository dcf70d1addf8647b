#include "cosim/finite_check.hpp"

#include <iomanip>

#include "common/errors.hpp"
#include "cosim/output.hpp"

namespace hbt::cosim {

std::vector<std::string> topLevelFieldNames(const std::string& definition) {
  std::vector<std::string> names;
  std::istringstream in(definition);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("===", 0) == 0) break;  // the nested types' definitions follow
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find('=') != std::string::npos) continue;  // a constant
    std::istringstream words(line);
    std::string type, name;
    if (words >> type >> name) names.push_back(name);
  }
  return names;
}

void Output::throwNotFinite(const std::string& field_value, double stamp_s) const {
  std::ostringstream os;
  os << std::fixed << std::setprecision(3) << "not finite in the output stamped t = " << stamp_s << " s";
  const std::size_t colon = field_value.rfind(": ");
  throw ModelDivergence(pub_.getTopic(), field_value.substr(0, colon) + " = " + field_value.substr(colon + 2),
                        os.str());
}

}  // namespace hbt::cosim
