// The bounded fuzz run of `make test-web` (issue 10, item 18): a fixed seed, a few thousand calls
// over every export of the WebAssembly core (see wasm_fuzz.mjs for the values and the contract).
// `make fuzz-web` runs the same fuzzer for long, with a random seed.
import { test } from "node:test";
import assert from "node:assert/strict";
import { describeReport, runFuzz } from "./wasm_fuzz.mjs";

/** The fixed seed and size of the bounded run (~10 s on one core). */
const SEED = 20251123;
const CALLS = 6000;
/** A call that runs longer than this is a hang. The slowest legitimate calls in the budget
 * (a polhode of 2e7 samples, an integration stopped by the binding's step limit of 1e7 steps)
 * take tens of seconds; the seed's calls take at most a few. */
const DEADLINE_MS = 60000;

test(`fuzz: ${CALLS} calls, seed ${SEED}: every result finite or an error naming an argument, never a trap or a hang`, { timeout: 10 * DEADLINE_MS }, async () => {
  const report = await runFuzz({ seed: SEED, calls: CALLS, deadlineMs: DEADLINE_MS });
  const text = describeReport(report, SEED);
  console.log(text);
  assert.equal(report.hang, undefined, text);
  assert.deepEqual(report.violations, [], text);
  assert.deepEqual(report.problems, [], text);
  // Coverage: every export was called, and there was an instance of every class to call it on.
  assert.deepEqual(report.uncovered, [], text);
  assert.deepEqual(report.noInstance, [], text);
  assert.ok(report.targets > 150, text);
  // The run is not all refusals: plenty of calls succeed, and every kind of error occurs.
  assert.ok(report.outcomes.ok > CALLS / 3, text);
  assert.ok(report.outcomes.TypeError > 0 && report.outcomes.PoinsotError > 0, text);
});
