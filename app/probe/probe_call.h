#pragma once

#include <tuple>
#include <type_traits>

#include "app/probe/call_table.h"
#include "app/probe/probe_answer.h"
#include "app/protocol/json_codec.h"

namespace raystep::probe {

// A contract function as the probe and the grader both know it, declared once: its name on the
// protocol, the type of its question and of its answer, and how this build answers it with its
// stage code (the submission's in a probe, the reference's in the grader). The probe's call table
// is built from these (add_calls), and the grader writes its queries through them (query), so a
// query whose arguments do not match the call does not compile, and a name is spelled in one
// place. The question and the answer cross as JSON by their types (json_codec.h).
template <class Question, class Answer>
struct ProbeCall {
    using QuestionType = Question;

    const char* name;
    Answer (*answer)(const Question& question);
};

namespace detail {

template <class Signature>
struct FunctionTraits;

template <class Result, class... Args>
struct FunctionTraits<Result(Args...)> {
    using Question = std::tuple<std::decay_t<Args>...>;
    using Answer = std::decay_t<Result>;
};

template <class Signature, Signature* Function>
typename FunctionTraits<Signature>::Answer answer_by_function(
    const typename FunctionTraits<Signature>::Question& question) {
    return std::apply(Function, question);
}

}  // namespace detail

/// The call of a stage function whose arguments are its question, a JSON array in order, and
/// whose result is its answer. The contract's signature is written out, which also picks the
/// function among overloads: function_call<double(const Vec3&, const Vec3&), &dot>("dot").
template <class Signature, Signature* Function>
constexpr auto function_call(const char* name) {
    using Traits = detail::FunctionTraits<Signature>;
    return ProbeCall<typename Traits::Question, typename Traits::Answer>{
        name, &detail::answer_by_function<Signature, Function>};
}

/// The grader's query of `call` on `question`.
template <class Question, class Answer>
grade::ProbeQuery query(const ProbeCall<Question, Answer>& call, const Question& question) {
    return {call.name, JsonCodec<Question>::write(question)};
}

/// The answer a probe gave to `call`, read as its type: throws where it is not one (an
/// unreadable answer, which a check reports as such).
template <class Question, class Answer>
Answer read_answer(const ProbeCall<Question, Answer>&, const Json& value) {
    return JsonCodec<Answer>::read(value);
}

/// `call` in the probe's table: the question read, answered by this build, the answer written.
template <class Question, class Answer>
void add_call(CallTable& table, const ProbeCall<Question, Answer>& call) {
    table[call.name] = [answer = call.answer](const Json& arguments) {
        return JsonCodec<Answer>::write(answer(JsonCodec<Question>::read(arguments)));
    };
}

/// Every call of a tuple of them, a stage's list.
template <class... Calls>
void add_calls(CallTable& table, const std::tuple<Calls...>& calls) {
    std::apply([&](const auto&... call) { (add_call(table, call), ...); }, calls);
}

}  // namespace raystep::probe
