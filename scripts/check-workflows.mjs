// GitHub's own reading of workflow files (scripts/check-workflows.sh runs this):
//
//   node scripts/check-workflows.mjs TOOLS FILE...
//
// TOOLS is the npm prefix @actions/workflow-parser is installed under. Its parser is the one
// GitHub's Actions language service (the editor's) uses, with GitHub's template schema: beyond a
// JSON schema it reads every ${{ }} expression and knows which contexts each key may use (runner
// in a job's env, for one, is an error). Prints each file's errors and exits 1 when any has one.
//
// Two things its package needs here. Node 20 imports a JSON file only with an import attribute,
// which the package's own import of its schema lacks: a loader hook hands the schema over as JSON.
// And the schema of version 0.3.61 gives the event name repository_dispatch the constant of
// branch_protection_rule, so that `on: [repository_dispatch]`, which GitHub runs (GitHub
// Classroom's workflow has it), is an error: the hook gives it its own name, and this says so.
import {readFileSync} from "node:fs";
import {register} from "node:module";
import {join} from "node:path";
import {pathToFileURL} from "node:url";

const [tools, ...files] = process.argv.slice(2);
const parserDir = join(tools, "node_modules", "@actions", "workflow-parser");
const schemaFile = join(parserDir, "dist", "workflow-v1.0.min.json");

const schema = JSON.parse(readFileSync(schemaFile, "utf8"));
const dispatch = schema.definitions?.["repository-dispatch-string"]?.string;
if (dispatch && dispatch.constant !== "repository_dispatch") {
  console.log(`note: @actions/workflow-parser's schema names repository_dispatch ` +
              `'${dispatch.constant}'; read as repository_dispatch`);
}

const hook = `
import {readFile} from "node:fs/promises";
export async function load(url, context, nextLoad) {
  if (!url.endsWith(".json")) return nextLoad(url, context);
  let source = await readFile(new URL(url), "utf8");
  if (url.endsWith("/workflow-v1.0.min.json")) {
    const schema = JSON.parse(source);
    const dispatch = schema.definitions?.["repository-dispatch-string"]?.string;
    if (dispatch) dispatch.constant = "repository_dispatch";
    source = JSON.stringify(schema);
  }
  return {format: "json", source, shortCircuit: true};
}`;
register("data:text/javascript," + encodeURIComponent(hook));
const parser = await import(pathToFileURL(join(parserDir, "dist", "index.js")).href);

let failed = 0;
for (const file of files) {
  const result = parser.parseWorkflow({name: file, content: readFileSync(file, "utf8")},
                                      new parser.NoOperationTraceWriter());
  const errors = result.context.errors.getErrors().map((error) => error.message);
  if (errors.length === 0 && result.value) {
    // Converting to the model checks what parsing leaves: job ids, needs, matrices.
    const template = await parser.convertWorkflowTemplate(result.context, result.value);
    errors.push(...(template.errors ?? []).map((error) => error.Message ?? String(error)));
  }
  if (errors.length > 0) {
    failed += 1;
    console.log(`FAIL ${file}: GitHub's workflow parser finds ${errors.length} error(s):`);
    for (const error of new Set(errors)) console.log(`  ${error}`);
  } else {
    console.log(`ok   ${file}: GitHub's workflow parser reads it without an error`);
  }
}
process.exit(failed > 0 ? 1 : 0);
