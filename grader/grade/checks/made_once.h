#pragma once

#include <exception>
#include <future>
#include <map>
#include <mutex>
#include <string>

namespace raystep::grade {

/// What a grader makes once per key however many checks ask for it, from several threads at once:
/// a measurement that checks share (stage 4's timed walks), renders every grade compares with
/// (stage 8's reference). The first asker makes it; the others wait for it, on their own threads.
template <class Result>
class MadeOnce {
  public:
    /// make()'s result for `key`, made by the first caller to ask; a later caller gets the same
    /// result, or the exception make() threw.
    template <class Make>
    const Result& get(const std::string& key, Make make) {
        std::promise<Result> promise;
        std::shared_future<Result> result;
        bool first = false;
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            auto found = made_.find(key);
            if (found == made_.end()) {
                found = made_.emplace(key, promise.get_future().share()).first;
                first = true;
            }
            result = found->second;
        }
        if (first) {
            try {
                promise.set_value(make());
            } catch (...) {
                promise.set_exception(std::current_exception());
            }
        }
        return result.get();
    }

  private:
    std::mutex mutex_;
    std::map<std::string, std::shared_future<Result>> made_;  ///< kept while the grader runs
};

}  // namespace raystep::grade
