#include "base/program/static_registry.h"

#include <string>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// Two kinds of entry, each with its registry, registered the way a layer above adds to a program:
// by static objects, before main.
struct Fruit {
    std::string name;
};
struct Vegetable {
    std::string name;
};
const StaticRegistry<Fruit>::Registration apple(Fruit{"apple"});
const StaticRegistry<Vegetable>::Registration leek(Vegetable{"leek"});
const StaticRegistry<Fruit>::Registration pear(Fruit{"pear"});

}  // namespace

TEST_CASE("StaticRegistry: entries registered by static objects, in their order", "[base]") {
    const std::vector<Fruit>& fruits = StaticRegistry<Fruit>::entries();
    REQUIRE(fruits.size() == 2);
    CHECK(fruits[0].name == "apple");
    CHECK(fruits[1].name == "pear");
}

TEST_CASE("StaticRegistry: each kind of entry has a registry of its own", "[base]") {
    REQUIRE(StaticRegistry<Vegetable>::entries().size() == 1);
    CHECK(StaticRegistry<Vegetable>::entries()[0].name == "leek");
}
