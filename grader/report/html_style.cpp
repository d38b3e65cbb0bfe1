#include "grader/report/html_style.h"

namespace raystep::grade {

std::string_view html_style() {
    // Outcome colours: green passed, red failed, orange when the probe died (crashed, timed
    // out), purple when it never ran (did not compile), grey for a stage not written yet.
    return R"css(
:root { --ink: #1d232b; --muted: #5b6673; --line: #d9dee4; --paper: #ffffff; --panel: #f5f7f9;
        --passed: #1e7b34; --failed: #c62828; --died: #d9730d; --compile: #7b3fa0;
        --missing: #6b7280; }
* { box-sizing: border-box; }
body { margin: 0; background: var(--panel); color: var(--ink);
       font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif; }
main { max-width: 1100px; margin: 0 auto; padding: 0 24px 32px; }
code, pre { font: 13px/1.4 ui-monospace, "SFMono-Regular", Menlo, "DejaVu Sans Mono", monospace; }
h1 { font-size: 22px; margin: 0 0 4px; }
h2 {
  font-size: 18px;
  margin: 28px 0 10px;
  padding-bottom: 4px;
  border-bottom: 2px solid var(--line);
}
h3 { font-size: 16px; margin: 0; flex: 1; }
a { color: #1f5fa8; }
.page-head { background: var(--ink); color: #fff; padding: 20px 24px; }
.page-head .inner { max-width: 1052px; margin: 0 auto; display: flex; gap: 24px;
                    align-items: flex-end; flex-wrap: wrap; }
.page-head .who { flex: 1; min-width: 280px; }
.page-head .submission { color: #b8c2cc; font-size: 13px; overflow-wrap: anywhere; }
.page-head .total { font-size: 30px; font-weight: 700; white-space: nowrap; }
.page-head .total small { font-size: 15px; font-weight: 400; color: #b8c2cc; }
.problem { background: #fdecea; border: 2px solid var(--failed); border-radius: 6px;
           padding: 10px 14px; margin: 16px 0 0; font-weight: 700; overflow-wrap: anywhere; }
.note { background: #fff8e1; border: 1px solid #f0d58a; border-radius: 6px; padding: 8px 12px;
        margin: 16px 0 0; }
table { border-collapse: collapse; background: var(--paper); }
th, td { text-align: left; padding: 6px 10px; border-bottom: 1px solid var(--line);
         vertical-align: top; }
th { font-weight: 600; color: var(--muted); font-size: 13px; }
.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.scores { width: 100%; border: 1px solid var(--line); }
.scores tfoot th, .scores tfoot td { color: var(--ink); font-size: 15px; font-weight: 700;
                                     border-bottom: 0; border-top: 2px solid var(--line); }
.bar { display: block; width: 100%; min-width: 120px; height: 10px; border-radius: 5px;
       background: #e6e9ed; overflow: hidden; margin-top: 6px; }
.bar span { display: block; height: 100%; background: var(--passed); }
.check { background: var(--paper); border: 1px solid var(--line);
         border-left: 5px solid var(--missing);
         border-radius: 6px; padding: 12px 16px; margin: 12px 0; }
.check.passed { border-left-color: var(--passed); }
.check.failed { border-left-color: var(--failed); }
.check.crashed, .check.timed-out { border-left-color: var(--died); }
.check.did-not-compile { border-left-color: var(--compile); }
.check-head { display: flex; align-items: center; gap: 12px; }
.badge { display: inline-block; min-width: 118px; text-align: center; padding: 2px 8px;
         border-radius: 12px; color: #fff; font-size: 12px; font-weight: 700;
         text-transform: uppercase;
         letter-spacing: 0.03em; background: var(--missing); white-space: nowrap; }
.badge.passed { background: var(--passed); }
.badge.failed { background: var(--failed); }
.badge.crashed, .badge.timed-out { background: var(--died); }
.badge.did-not-compile { background: var(--compile); }
.points { font-weight: 700; font-variant-numeric: tabular-nums; white-space: nowrap; }
.meta { color: var(--muted); font-size: 13px; margin: 6px 0 0; }
.visibility { color: #8a5a00; background: #fff3cd; border-radius: 4px; padding: 0 6px; }
.summary { margin: 8px 0 0; overflow-wrap: anywhere; }
.metrics { margin-top: 10px; border: 1px solid var(--line); }
.metrics td { font-variant-numeric: tabular-nums; }
.images { display: grid; grid-template-columns: repeat(3, 1fr); gap: 12px; margin-top: 12px; }
figure { margin: 0; }
figure img { display: block; width: 100%; height: auto; image-rendering: pixelated;
             border: 1px solid var(--line); background: #000; }
figcaption { color: var(--muted); font-size: 13px; text-align: center; margin-top: 4px; }
.missing-image { border: 1px dashed var(--line); color: var(--muted); padding: 24px 8px;
                 text-align: center; font-size: 13px; overflow-wrap: anywhere; }
.counterexamples {
  width: 100%;
  margin-top: 12px;
  border: 1px solid var(--line);
  table-layout: fixed;
}
.counterexamples th:first-child { width: 36px; }
.counterexamples td { white-space: pre-wrap; overflow-wrap: anywhere; font-size: 13px; }
.counterexamples tr.reproduce td { background: var(--panel); border-bottom: 2px solid var(--line); }
.counterexamples tr.reproduce code { white-space: pre-wrap; overflow-wrap: anywhere; }
details { margin-top: 12px; }
summary { cursor: pointer; color: var(--muted); font-size: 13px; }
pre { background: #1d232b; color: #e8edf2; padding: 10px 12px; border-radius: 6px;
      white-space: pre-wrap; overflow-wrap: anywhere; max-height: 420px; overflow: auto;
      margin: 6px 0 0; }
.chart svg {
  max-width: 100%;
  height: auto;
  background: var(--paper);
  border: 1px solid var(--line);
}
footer { color: var(--muted); font-size: 13px; margin-top: 32px; }
@media (max-width: 720px) { .images { grid-template-columns: 1fr; } }
)css";
}

}  // namespace raystep::grade
