// 64-bit FNV-1a (base/math/fnv1a.h) against the published test vectors of Fowler, Noll and Vo.

#include "base/math/fnv1a.h"

#include "base/testing/catch.h"

TEST_CASE("fnv1a: the digest of nothing is the offset basis", "[base]") {
    CHECK(raystep::fnv1a("") == 0xcbf29ce484222325u);
}

TEST_CASE("fnv1a: one byte and a word give the published digests", "[base]") {
    CHECK(raystep::fnv1a("a") == 0xaf63dc4c8601ec8cu);
    CHECK(raystep::fnv1a("foobar") == 0x85944171f73967e8u);
}

TEST_CASE("fnv1a: a digest goes on from where another ended", "[base]") {
    CHECK(raystep::fnv1a("bar", raystep::fnv1a("foo")) == raystep::fnv1a("foobar"));
}

TEST_CASE("fnv1a_fold: a byte folds as the value it is", "[base]") {
    CHECK(raystep::fnv1a_fold(raystep::kFnv1aBasis, 'a') == raystep::fnv1a("a"));
}
