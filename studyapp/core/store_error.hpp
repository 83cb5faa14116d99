// StoreError: a failure inside the results store's database (SQLite or PostgreSQL); what() names the
// location. `refused()` is true when the database refused the row itself (a unique, foreign-key or
// check constraint, a value that is not JSON): the caller's input, not the database, is at fault.
#pragma once
#include <stdexcept>
#include <string>

namespace ms {

class StoreError : public std::runtime_error {
 public:
  StoreError(const std::string& message, bool refused) : std::runtime_error(message), refused_(refused) {}
  bool refused() const { return refused_; }

 private:
  bool refused_;
};

}  // namespace ms
