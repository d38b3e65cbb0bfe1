#include "grader/grade/shard.h"

#include <regex>
#include <stdexcept>

namespace raystep::grade {

Shard parse_shard(const std::string& text) {
    static const std::regex form("([0-9]{1,6})/([0-9]{1,6})");
    std::smatch parts;
    if (!std::regex_match(text, parts, form)) {
        throw std::invalid_argument("'" + text + "' is not a shard: give I/N, as 2/8");
    }
    const Shard shard{std::stoi(parts[1].str()), std::stoi(parts[2].str())};
    if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
        throw std::invalid_argument("shard " + text + ": I must be from 1 to N");
    }
    return shard;
}

}  // namespace raystep::grade
