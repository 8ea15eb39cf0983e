// The results of `impossible bench` as a table, JSON and CSV (schema in
// bench/README.md).
#pragma once

#include <ostream>
#include <string>

#include "bench/run.hpp"

namespace impossible::bench {

void write_bench_table(const BenchResult& result, const BenchOptions& options, std::ostream& out);
std::string bench_json(const BenchResult& result, const BenchOptions& options);
std::string bench_csv(const BenchResult& result);

}  // namespace impossible::bench
