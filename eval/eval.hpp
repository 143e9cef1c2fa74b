#pragma once
// The evaluation library's entry points (used by `wifislam eval`, `compare` and `demo`):
//   RunEvaluation ev = eval::evaluate_run(run_dir, dataset_dir, eval::EvalOptions{});
//   eval::write_evaluation(run_dir / "eval", ev, run_dir, dataset_dir, /*plots=*/true);

#include "eval/eval_options.hpp"
#include "eval/evaluate_run.hpp"
#include "eval/report_writer.hpp"
#include "eval/run_evaluation.hpp"
