#include "app/probe/call_reply.h"

#include <stdexcept>
#include <typeinfo>

#include "base/errors/not_implemented.h"

namespace raystep::probe {

namespace {

// How much of a malformed line a report quotes.
constexpr std::size_t kShownBytes = 200;

// The standard exceptions the contracts name, by name; anything else is "other".
std::string exception_type(const std::exception& error) {
    if (dynamic_cast<const std::domain_error*>(&error)) return "domain_error";
    if (dynamic_cast<const std::invalid_argument*>(&error)) return "invalid_argument";
    if (dynamic_cast<const std::out_of_range*>(&error)) return "out_of_range";
    if (dynamic_cast<const std::logic_error*>(&error)) return "logic_error";
    if (dynamic_cast<const std::runtime_error*>(&error)) return "runtime_error";
    return "other";
}

}  // namespace

Json reply_to(const CallTable& table, const Json& query) {
    Json reply = {{"id", query.value("id", Json(nullptr))}};
    try {
        const std::string name = query.at("call").get<std::string>();
        const auto call = table.find(name);
        if (call == table.end()) throw std::invalid_argument("the probe has no call " + name);
        reply["result"] = call->second(query.at("args"));
    } catch (const NotImplemented& stub) {
        reply["not_implemented"] = stub.what();
    } catch (const std::exception& error) {
        reply["threw"] = {{"type", exception_type(error)}, {"message", error.what()}};
    } catch (...) {
        reply["threw"] = {{"type", "other"},
                          {"message", "a thrown value that is not a std::exception"}};
    }
    return reply;
}

grade::ProbeAnswer malformed_reply(const std::string& line, const std::string& cause) {
    grade::ProbeAnswer answer;
    answer.kind = grade::ProbeAnswer::Kind::malformed;
    const std::string shown =
        line.size() > kShownBytes ? line.substr(0, kShownBytes) + "..." : line;
    answer.message = "received \"" + shown + "\": " + cause;
    return answer;
}

grade::ProbeAnswer read_reply(const Json& reply, const std::string& line) {
    using Kind = grade::ProbeAnswer::Kind;
    grade::ProbeAnswer answer;
    if (reply.contains("result")) {
        answer.kind = Kind::result;
        answer.value = reply["result"];
    } else if (reply.contains("not_implemented") && reply["not_implemented"].is_string()) {
        answer.kind = Kind::not_implemented;
        answer.message = reply["not_implemented"].get<std::string>();
    } else if (reply.contains("threw") && reply["threw"].is_object()) {
        const Json& threw = reply["threw"];
        answer.kind = Kind::threw;
        answer.exception_type = threw.value("type", "other");
        answer.message = threw.value("message", "");
    } else {
        answer = malformed_reply(line, "an answer with neither result, not_implemented nor threw");
    }
    return answer;
}

grade::ProbeAnswer answer_in_process(const CallTable& table, const grade::ProbeQuery& query) {
    const Json reply = reply_to(table, {{"call", query.call}, {"args", query.args}});
    return read_reply(reply, reply.dump(-1, ' ', false, Json::error_handler_t::replace));
}

}  // namespace raystep::probe
