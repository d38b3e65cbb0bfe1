// The page of `raystep view` (app/view/view_server.cpp serves it and answers its /api/ requests).
// It asks for a render, draws its tiles as they finish, shows the reference beside it or under a
// slider, traces the pixel a click picks, and renders again when the server says the scene file
// or the program changed. No library: what it does fits in one file a student can read.
"use strict";

const page = {
  server: null,            // the server's id: a new one means the program was rebuilt
  sceneGeneration: null,   // counts the scene's loads on the server
  scene: null,             // /api/state's scene
  view: "full",
  generation: 0,           // the render we draw
  sequence: 0,             // the last tile drawn
  renderState: "idle",
  selected: null,          // the clicked pixel, {x, y}
  zoom: 1,                 // the images' zoom as drawn: screen pixels (CSS) per image pixel
  windowZoom: null,        // the zoom chosen in the window; null: fitted to it
  zoomBeforeFullScreen: null,
  fullScreenZoom: null,    // the zoom chosen in full screen; null: as large as fits
  controls: {},            // the controls' values as the form holds them
  referenceRequest: 0,     // counts showReference's calls: only the latest may draw
  traceRequest: 0,         // counts trace requests: only the latest may fill the panel
  renderError: "",         // why the server refused the last render asked for
};

const $ = (id) => document.getElementById(id);

async function api(path, params = {}) {
  const query = new URLSearchParams(params).toString();
  const response = await fetch("/api/" + path + (query ? "?" + query : ""),
                               { headers: { "X-Raystep": "1" } });
  if (!response.ok) {
    let message = response.statusText;
    try { message = (await response.json()).error; } catch (_) { /* not JSON */ }
    throw new Error(message);
  }
  return response;
}

// A frame: 4 bytes of header length, the JSON header, then each tile's RGBA bytes.
async function readFrame(response) {
  const buffer = await response.arrayBuffer();
  const length = new DataView(buffer).getUint32(0, true);
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, length)));
  let offset = 4 + length;
  header.images = header.tiles.map(([x, y, w, h]) => {
    const pixels = new Uint8ClampedArray(buffer, offset, w * h * 4);
    offset += w * h * 4;
    return { x, y, image: new ImageData(pixels, w, h) };
  });
  return header;
}

function setStatus(text) { $("status").textContent = text; }

function controlValues() {
  const values = {};
  for (const element of $("controls").elements) {
    if (element.name) values[element.name] = element.value;
  }
  return values;
}

// ---- state: the scene, its views and controls ----------------------------------------------

async function loadState() {
  const state = await (await api("state")).json();
  if (!page.scene || page.scene.file !== state.scene.file) {
    page.view = state.scene.first_view || page.view;  // another scene: the view it names first
    clearReference();
  }
  page.server = state.server;
  page.scene = state.scene;
  page.sceneGeneration = state.scene.generation;
  fillSceneList(state.scenes, state.scene.file);
  fillViews(state.views);
  fillControls(state.scene.controls || []);
  fillDemos(state.demos);
  showSceneError(state.scene.error);
  // Without a scene (`raystep view` alone) the page is the demos.
  $("images").hidden = !state.scene.file;
  document.querySelector("aside").hidden = !state.scene.file;
  sizeCanvas($("render"), state.scene.width || 1, state.scene.height || 1);
  fitZoomToWindow();
  layout();
  return state;
}

// Until the zoom is chosen, the largest whole zoom at which the render and the reference beside
// it fit beside the side panel.
function fitZoomToWindow() {
  if (page.windowZoom !== null || !page.scene || !page.scene.width || isFullScreen()) return;
  const beside = $("reference-mode").value === "beside" ? 2 : 1;
  const room = window.innerWidth - document.querySelector("aside").offsetWidth - 80;
  const zoom = Math.floor(room / (beside * page.scene.width));
  setZoom(Math.min(4, Math.max(1, zoom)));
}

function fillSceneList(scenes, file) {
  const list = $("scene-list");
  list.replaceChildren();
  const current = scenes.find((name) => file && file.endsWith("scenes/" + name));
  if (file && !current) list.append(new Option(file, "", true, true));
  if (!file) list.append(new Option("(choose a scene)", "", true, true));
  for (const name of scenes) list.append(new Option(name, name, false, name === current));
}

function fillViews(views) {
  const group = $("views");
  group.replaceChildren();
  for (const name of views) {
    const button = document.createElement("button");
    button.type = "button";
    button.textContent = name;
    button.dataset.view = name;
    button.setAttribute("aria-pressed", String(name === page.view));
    button.addEventListener("click", () => { page.view = name; startRender(); });
    group.append(button);
  }
}

function fillControls(controls) {
  const form = $("controls");
  form.replaceChildren();
  for (const control of controls) {
    const label = document.createElement("label");
    label.append(control.label + " ");
    let input;
    if (control.kind === "choice") {
      input = document.createElement("select");
      for (const choice of control.choices) input.append(new Option(choice, choice));
    } else {
      input = document.createElement("input");
      input.type = "text";
      input.inputMode = "decimal";
    }
    input.name = control.name;
    input.value = page.controls[control.name] ?? control.value;
    input.addEventListener("change", () => { page.controls = controlValues(); startRender(); });
    label.append(input);
    form.append(label);
  }
  page.controls = controlValues();
  // Only what the scene uses has a control (app/view/scene_controls.h): a scene of stages 1 to 5
  // has none, and says so.
  form.hidden = controls.length === 0;
  $("controls-hint").hidden = controls.length === 0;
  $("no-controls").hidden = controls.length !== 0;
  document.body.dataset.controls = String(controls.length);
}

// A scene that does not load: its error, file:line, and nothing left of what it showed before
// (the trace, its comparison, the reference's caption) that would read as still true.
function showSceneError(error) {
  $("scene-error").hidden = !error;
  $("scene-error").textContent = error || "";
  if (!error) return;
  setStatus("the scene does not load: the message above says where");
  clearTrace("The scene does not load; once it does, the clicked pixel is traced again.");
}

// ---- the render and its tiles ---------------------------------------------------------------

// The view's button pressed, and its name over the render.
function markView() {
  for (const button of $("views").children) {
    button.setAttribute("aria-pressed", String(button.dataset.view === page.view));
  }
  $("render-caption").textContent = page.view;
}

async function startRender() {
  markView();
  if (!page.scene || !page.scene.width) return;
  try {
    const answer = await (await api("render", { view: page.view, ...page.controls })).json();
    showRenderError("");
    page.generation = answer.generation;
    page.sequence = 0;
    page.renderState = "rendering";
    sizeCanvas($("render"), page.scene.width, page.scene.height);
    $("render").getContext("2d").clearRect(0, 0, page.scene.width, page.scene.height);
    showReference();
    if (page.selected) tracePixel(page.selected.x, page.selected.y);
  } catch (error) {
    showRenderError(error.message);
  }
}

// A render the server refused (a control's value it does not take) stays said, and its control
// marked, until a render is started: the image beside it is the last one rendered, not what the
// controls say.
function showRenderError(message) {
  page.renderError = message;
  const refused = /^control (\w+):/.exec(message);
  for (const element of $("controls").elements) {
    element.classList.toggle("refused", Boolean(refused) && element.name === refused[1]);
  }
  if (message) setStatus("not rendered: " + message + " (the image is the last render)");
}

function sizeCanvas(canvas, width, height, zoom = page.zoom) {
  if (canvas.width !== width) canvas.width = width;
  if (canvas.height !== height) canvas.height = height;
  canvas.style.width = width * zoom + "px";
  canvas.style.height = height * zoom + "px";
}

// Asks for the tiles since the last one drawn: often while rendering, then now and then, to see
// a render the server started itself after the scene file changed.
async function pollTiles() {
  try {
    const frame = await readFrame(await api("tiles",
                                            { generation: page.generation, since: page.sequence }));
    if (frame.scene_generation !== page.sceneGeneration) await onSceneReloaded();
    if (frame.generation !== page.generation) {
      page.generation = frame.generation;
      $("render").getContext("2d").clearRect(0, 0, frame.width, frame.height);
      followRender(frame);
    }
    if (frame.width) sizeCanvas($("render"), frame.width, frame.height);
    const context = $("render").getContext("2d");
    for (const tile of frame.images) context.putImageData(tile.image, tile.x, tile.y);
    page.sequence = frame.sequence;
    page.renderState = frame.state;
    const total = frame.width * frame.height;
    if ((page.scene && page.scene.error) || page.renderError) {
      // Said by showSceneError or showRenderError, and kept.
    } else if (frame.state === "rendering") {
      const percent = total ? Math.floor((100 * frame.pixels_done) / total) : 0;
      // A view that averages samples renders in passes of more samples each: the image
      // converges as the passes come.
      const pass =
        frame.target_samples > 1 ? `, ${frame.samples} of ${frame.target_samples} spp` : "";
      setStatus(`rendering ${frame.view}${pass}: ${percent}% (${frame.seconds.toFixed(1)} s)`);
    } else if (frame.state === "done") {
      setStatus(`${frame.view}: done in ${frame.seconds.toFixed(2)} s`);
    } else if (frame.state === "failed") {
      setStatus(`${frame.view} stopped: ${frame.error}`);
    }
    document.body.dataset.render = frame.state;
    document.body.dataset.generation = String(frame.generation);
    setTimeout(pollTiles, frame.state === "rendering" ? 100 : 500);
  } catch (error) {
    setStatus("waiting for raystep view (" + error.message + ")");
    setTimeout(pollTiles, 1000);
  }
}

// One server renders one image: a render another page started (a second tab, the lectern's
// laptop) is the one this page now shows, so its buttons and controls follow it.
function followRender(frame) {
  for (const element of $("controls").elements) {
    if (element.name in frame.controls) element.value = frame.controls[element.name];
  }
  page.controls = controlValues();
  if (frame.view === page.view) return;
  page.view = frame.view;
  markView();
  showReference();
  if (page.selected) tracePixel(page.selected.x, page.selected.y);
}

async function onSceneReloaded() {
  await loadState();
  showReference();
  if (page.selected && !page.scene.error) tracePixel(page.selected.x, page.selected.y);
}

// ---- the reference ---------------------------------------------------------------------------

async function showReference() {
  // Only the latest call may draw: an answer that comes after a later call's is dropped.
  const request = ++page.referenceRequest;
  const mode = $("reference-mode").value;
  const references = (page.scene && page.scene.reference_views) || [];
  const has = references.includes(page.view);
  $("reference-figure").hidden = mode !== "beside";
  $("slider").hidden = mode !== "slider" || !has;
  clearReference();
  if (mode === "off") return;
  if (page.scene && page.scene.error) {
    $("reference-caption").textContent = "";
    return;
  }
  if (!has) {
    $("reference-caption").textContent = references.length
      ? `none for ${page.view}; the release ships ${references.join(", ")}`
      : "none shipped for this scene (a student release ships them in reference/ beside it)";
    sizeCanvas($("reference"), 1, 1);
    return;
  }
  $("reference-caption").textContent = `${page.view}: loading (${page.scene.reference_source})`;
  try {
    const blob = await (await api("reference", { view: page.view })).blob();
    const bitmap = await createImageBitmap(blob);
    if (request !== page.referenceRequest) return;
    $("reference-overlay").hidden = mode !== "slider";
    for (const canvas of [$("reference"), $("reference-overlay")]) {
      sizeCanvas(canvas, bitmap.width, bitmap.height);
      canvas.getContext("2d").drawImage(bitmap, 0, 0);
    }
    $("reference-caption").textContent = page.view;
    $("reference-source").textContent = `(${page.scene.reference_source})`;
    applySlider();
    layout();
  } catch (error) {
    if (request === page.referenceRequest) $("reference-caption").textContent = error.message;
  }
}

// Until a view's reference arrives, no other scene's or view's stands in for it.
function clearReference() {
  $("reference-overlay").hidden = true;
  $("reference-source").textContent = "";
  $("reference").getContext("2d").clearRect(0, 0, $("reference").width, $("reference").height);
}

function applySlider() {
  const percent = 100 - Number($("slider").value);
  $("reference-overlay").style.clipPath = `inset(0 0 0 ${100 - percent}%)`;
}

// ---- the trace panel -------------------------------------------------------------------------

function pixelAt(event) {
  const canvas = $("render");
  const box = canvas.getBoundingClientRect();
  const x = Math.floor(((event.clientX - box.left) * canvas.width) / box.width);
  const y = Math.floor(((event.clientY - box.top) * canvas.height) / box.height);
  return { x: Math.min(Math.max(x, 0), canvas.width - 1),
           y: Math.min(Math.max(y, 0), canvas.height - 1) };
}

function placeMarker() {
  const marker = $("marker");
  if (!page.selected) { marker.hidden = true; return; }
  const zoom = page.zoom;
  marker.hidden = false;
  marker.style.left = page.selected.x * zoom - 1 + "px";
  marker.style.top = page.selected.y * zoom - 1 + "px";
  marker.style.width = marker.style.height = zoom + "px";
}

// A click's trace, then its comparison: the comparison can wait for raystep-reference to write
// the scene's reference first (in the instructor's build), and this build's trace does not.
async function tracePixel(x, y) {
  page.selected = { x, y };
  placeMarker();
  const panel = $("trace-panel");
  panel.dataset.state = "tracing";
  $("trace-pixel").textContent = `(${x}, ${y}), view ${page.view}`;
  // A click's answers arriving after a later click's are dropped.
  const request = ++page.traceRequest;
  const params = { x, y, view: page.view, ...page.controls };
  try {
    const trace = await (await api("trace", params)).json();
    if (request !== page.traceRequest) return;
    showTrace(trace);
    $("comparison-unavailable").hidden = false;
    $("comparison-unavailable").textContent =
      "Comparing with the reference (the first time, raystep-reference writes it: as long as one " +
      "render)...";
    const compared = await (await api("compare", params)).json();
    if (request !== page.traceRequest) return;
    showComparison(compared);
    panel.dataset.pixel = `${x},${y}`;
    panel.dataset.view = page.view;
    panel.dataset.state = "ready";
  } catch (error) {
    if (request !== page.traceRequest) return;
    clearTrace("no trace: " + error.message);
    panel.dataset.state = "failed";
  }
}

function clearTrace(hint) {
  $("trace-lines").replaceChildren();
  $("trace-title").hidden = true;
  $("comparison-box").hidden = true;
  $("comparison-unavailable").hidden = true;
  $("trace-hint").hidden = false;
  $("trace-hint").textContent = hint;
}

// What a line of the trace is about, for its colour: the lecture's steps, in the order the
// renderer takes them.
function stepKind(line) {
  const text = line.trim();
  if (text.startsWith("camera ray")) return "step-camera";
  if (text.startsWith("closest_hit") || / hit t=/.test(text)) return "step-hit";
  if (text.startsWith("shadow ray")) return "step-shadow";
  if (/^(point|directional|spot|quad) light/.test(text)) return "step-light";
  if (/^(reflected|refracted) ray/.test(text)) return "step-bounce";
  if (text.startsWith("value:")) return "step-value";
  return "";
}

function showTrace(trace) {
  $("trace-hint").hidden = true;
  $("trace-title").hidden = false;
  $("comparison-box").hidden = true;
  const lines = $("trace-lines");
  lines.replaceChildren();
  trace.lines.forEach((line, k) => {
    const item = document.createElement("li");
    item.textContent = line;
    item.className = trace.stopped && k === trace.lines.length - 1 ? "stopped" : stepKind(line);
    lines.append(item);
  });
}

function showComparison(compared) {
  const comparison = compared.comparison;
  $("comparison-box").hidden = !comparison;
  $("comparison-unavailable").hidden = !compared.comparison_unavailable;
  $("comparison-unavailable").textContent = compared.comparison_unavailable
    ? "No comparison: " + compared.comparison_unavailable : "";
  if (!comparison) return;
  const notes = $("comparison-notes");
  notes.replaceChildren(...comparison.notes.map((note) => {
    const item = document.createElement("li");
    item.textContent = note;
    return item;
  }));
  const body = $("comparison").tBodies[0];
  body.replaceChildren();
  comparison.rows.forEach((row, k) => {
    const tr = body.insertRow();
    const first = comparison.first_difference === k;
    tr.className = (first ? "first " : "") + (row.same ? "" : "differs");
    for (const text of [first ? ">>" : "", row.quantity, row.ours, row.reference]) {
      tr.insertCell().textContent = text;
    }
  });
  const verdict = $("comparison-verdict");
  if (comparison.first_difference !== null) {
    const row = comparison.rows[comparison.first_difference];
    verdict.textContent = `first difference: ${row.quantity}, ${row.ours} here against ` +
                          `${row.reference} in the reference`;
    verdict.className = "different";
  } else if (comparison.stopped) {
    verdict.textContent = "stopped: " + comparison.stop;
    verdict.className = "different";
  } else {
    verdict.textContent = "the traces are the same";
    verdict.className = "same";
  }
}

// ---- demos -----------------------------------------------------------------------------------

function fillDemos(demos) {
  const list = $("demo-list");
  if (list.children.length) return;
  for (const demo of demos) {
    const row = document.createElement("div");
    const figure = document.createElement("button");
    figure.type = "button";
    figure.textContent = "figure";
    figure.addEventListener("click", () => showDemoFigure(demo));
    row.append(figure);
    if (demo.scene) {
      const live = document.createElement("button");
      live.type = "button";
      live.textContent = "explore live";
      live.addEventListener("click", () => exploreDemo(demo));
      row.append(live);
    }
    if (demo.parameter.name) row.append(demoParameterControl(demo));
    row.append(`${demo.name}: ${demo.description}`);
    list.append(row);
  }
}

// A demo whose parameter is its own, not its scene's (watertight's triangle test): a choice that
// draws the demo at that value alone.
function demoParameterControl(demo) {
  const select = document.createElement("select");
  select.setAttribute("aria-label", demo.parameter.label);
  select.append(new Option(demo.parameter.label + ": all", ""));
  for (const choice of demo.parameter.choices) select.append(new Option(choice, choice));
  select.addEventListener("change", () => showDemoFigure(demo, select.value));
  return select;
}

// The demos take the scene's place while they are shown, so that the figure is drawn where the
// window shows it, not under the render.
function showDemos(shown) {
  $("demos").hidden = !shown;
  document.querySelector("main").hidden = shown;
  $("show-demos").setAttribute("aria-pressed", String(shown));
  if (shown) window.scrollTo(0, 0);
  layout();
}

// The room the figure has: its column's width, and the window's height under the header and the
// caption.
function demoRoom() {
  const figure = $("demo-figure");
  const top = Math.max(0, $("demo-canvas").getBoundingClientRect().top -
                              figure.getBoundingClientRect().top);
  const header = document.querySelector("header").offsetHeight;
  return { width: figure.clientWidth,
           height: window.innerHeight - header - top - 2 * emPixels() };
}

// The page's text height in CSS pixels: the gaps and paddings of view.css are in it.
function emPixels() {
  return parseFloat(getComputedStyle(document.body).fontSize) || 14;
}

// The size to ask the server for: the room in the screen's own pixels, 4:3 to 16:9, from 320 x 240
// (the smallest the server draws, app/demo/demo_size.h) to 1920 x 1080, past which a figure takes
// long to render and the page waits for it. A projector shows text drawn at its size, not a small
// figure scaled up, nor a large one scaled down.
function demoRequestSize() {
  const room = demoRoom();
  const ratio = window.devicePixelRatio || 1;
  let width = Math.max(1, room.width) * ratio;
  let height = Math.max(1, room.height) * ratio;
  if (width > height * 16 / 9) width = height * 16 / 9;
  if (width < height * 4 / 3) height = width * 3 / 4;
  const scale = Math.max(Math.min(1, 1920 / width, 1080 / height), 320 / width, 240 / height);
  return `${Math.round(width * scale)}x${Math.round(height * scale)}`;
}

// The figure whole in its room: scaled down (or up) to the largest size that fits.
function fitDemoFigure() {
  const canvas = $("demo-canvas");
  if ($("demos").hidden || $("demo-figure").hidden || canvas.width <= 1) return;
  const room = demoRoom();
  const scale = Math.max(0.05, Math.min(room.width / canvas.width, room.height / canvas.height));
  canvas.style.width = Math.floor(canvas.width * scale) + "px";
  canvas.style.height = Math.floor(canvas.height * scale) + "px";
}

async function showDemoFigure(demo, choice = "") {
  $("demo-figure").hidden = false;
  $("demo-caption").textContent = `rendering ${demo.name}...`;
  const params = { name: demo.name, size: demoRequestSize() };
  if (choice) params[demo.parameter.name] = choice;
  try {
    const frame = await readFrame(await api("demo", params));
    const tile = frame.images[0];
    sizeCanvas($("demo-canvas"), tile.image.width, tile.image.height, 1);
    $("demo-canvas").getContext("2d").putImageData(tile.image, 0, 0);
    $("demo-caption").textContent = `raystep demo ${demo.name} --size ${params.size}` +
                                    (choice ? ` (${demo.parameter.label}: ${choice})` : "");
    fitDemoFigure();
    $("demo-figure").scrollIntoView({ block: "nearest" });
  } catch (error) {
    $("demo-caption").textContent = `${demo.name} stopped: ${error.message}`;
  }
}

async function exploreDemo(demo) {
  await openScene(demo.scene);
  page.view = demo.view;
  const preset = Object.fromEntries(new URLSearchParams(demo.controls));
  for (const element of $("controls").elements) {
    if (element.name in preset) element.value = preset[element.name];
  }
  page.controls = controlValues();
  showDemos(false);
  await startRender();
}

async function openScene(name) {
  try {
    await api("open", { scene: name });
    page.controls = {};
    page.selected = null;
    placeMarker();
    await loadState();
  } catch (error) {
    setStatus("cannot open " + name + ": " + error.message);
  }
}

// ---- a rebuilt program -----------------------------------------------------------------------

// The server starts itself again after a rebuild; its new id tells the page to ask again.
async function watchServer() {
  try {
    const state = await (await api("state")).json();
    $("program-note").hidden = !state.program_note;
    $("program-note").textContent = state.program_note;
    if (page.server !== null && state.server !== page.server) {
      setStatus("the program was rebuilt: rendering again");
      await loadState();
      await startRender();
    }
  } catch (_) {
    setStatus("raystep view does not answer: it is restarting, or it stopped (its terminal says " +
              "why); this page waits for it");
  }
  setTimeout(watchServer, 1000);
}

// ---- zoom and full screen ---------------------------------------------------------------------

function setZoom(zoom) {
  drawAtZoom(zoom);
  // The list holds 1x to 4x, and the zoom drawn when it is another (fitted to full screen).
  const select = $("zoom");
  const value = String(page.zoom);
  for (const option of [...select.options]) {
    if (!["1", "2", "3", "4", value].includes(option.value)) option.remove();
  }
  if (![...select.options].some((option) => option.value === value)) {
    const label = Number.isInteger(page.zoom) ? value : page.zoom.toFixed(2);
    select.append(new Option(label + "x", value));
  }
  select.value = value;
}

// The images at `zoom`, the list left as it is: for the trials of fitFullScreen.
function drawAtZoom(zoom) {
  page.zoom = Number(zoom);
  for (const id of ["render", "reference", "reference-overlay"]) {
    const canvas = $(id);
    sizeCanvas(canvas, canvas.width, canvas.height);
  }
  placeMarker();
}

function isFullScreen() {
  return document.body.classList.contains("full-screen");
}

// What changes the room the images have (the window's size, the browser's zoom, full screen, the
// reference's place, a new scene) sizes them again.
function layout() {
  const header = document.querySelector("header");
  document.documentElement.style.setProperty("--header-height", header.offsetHeight + "px");
  fitFullScreen();
  fitDemoFigure();
}

// True when something of the images or the controls is outside the window, or the page scrolls.
function overflowsWindow() {
  const root = document.documentElement;
  if (root.scrollHeight > window.innerHeight + 1 || root.scrollWidth > window.innerWidth + 1) {
    return true;
  }
  const aside = document.querySelector("aside");
  const asideLeft = aside.offsetParent ? aside.getBoundingClientRect().left : window.innerWidth;
  const outside = [...document.querySelectorAll("#images canvas, #slider")].some((element) => {
    if (!element.offsetParent) return false;
    const box = element.getBoundingClientRect();
    return box.bottom > window.innerHeight + 0.5 || box.right > asideLeft + 0.5 ||
           box.left < -0.5;
  });
  // The reference beside the render, not over it.
  const reference = $("reference");
  return outside || (Boolean(reference.offsetParent) &&
                     reference.getBoundingClientRect().left <
                         $("render").getBoundingClientRect().right - 0.5);
}

// In full screen: the images as large as fits beside the controls, at the zoom chosen in full
// screen at most. Whole zooms from 1 up, so that each image pixel stays a square of the same
// size; below 1 where even 1x does not fit (a small window, or the browser zoomed in). The room
// is measured with the images at their smallest, then the zoom is taken down until nothing
// overflows: captions wrap and the header's height varies, and this way neither is assumed.
function fitFullScreen() {
  if (!isFullScreen() || document.querySelector("main").hidden) return;
  const canvas = $("render");
  if (!page.scene || !page.scene.width || canvas.width <= 1) return;
  const beside = !$("reference-figure").hidden && $("reference").width > 1;
  const gap = beside ? emPixels() : 0;
  drawAtZoom(1 / Math.max(canvas.width, canvas.height));
  const room = $("images").clientWidth - gap;
  const below = $("slider").hidden ? 0 : $("slider").offsetHeight;
  const height = window.innerHeight - canvas.getBoundingClientRect().top - below - emPixels();
  const width = beside ? room / (canvas.width + $("reference").width) : room / canvas.width;
  let zoom = Math.min(width, height / canvas.height, page.fullScreenZoom ?? Infinity);
  zoom = zoom >= 1 ? Math.floor(zoom) : Math.floor(zoom * 100) / 100;
  drawAtZoom(Math.max(zoom, 0.05));
  while (overflowsWindow() && page.zoom > 0.05) {
    drawAtZoom(page.zoom > 1 ? page.zoom - 1 : Math.floor(page.zoom * 95) / 100);
  }
  setZoom(page.zoom);
}

// ---- start -----------------------------------------------------------------------------------

window.addEventListener("DOMContentLoaded", async () => {
  $("render").addEventListener("click", (event) => {
    const { x, y } = pixelAt(event);
    tracePixel(x, y);
  });
  $("reference-mode").addEventListener("change", () => { showReference(); layout(); });
  $("slider").addEventListener("input", applySlider);
  $("zoom").addEventListener("change", () => {
    if (isFullScreen()) {
      page.fullScreenZoom = Number($("zoom").value);
      setZoom(page.fullScreenZoom);
      fitFullScreen();
    } else {
      page.windowZoom = $("zoom").value;
      setZoom($("zoom").value);
    }
  });
  $("scene-list").addEventListener("change", async () => {
    if (!$("scene-list").value) return;
    await openScene($("scene-list").value);
    await startRender();
  });
  $("show-demos").addEventListener("click", () => showDemos($("demos").hidden));
  $("full-screen").addEventListener("click", () => {
    if (document.fullscreenElement) {
      document.exitFullscreen();
    } else {
      document.documentElement.requestFullscreen().catch(() => {});
    }
  });
  document.addEventListener("fullscreenchange", () => {
    const full = Boolean(document.fullscreenElement);
    if (full === isFullScreen()) return;
    document.body.classList.toggle("full-screen", full);
    if (full) {
      page.zoomBeforeFullScreen = page.zoom;
      page.fullScreenZoom = null;
      // The controls are what the class reads the parameters from: open, whatever they were.
      $("controls-box").open = true;
    } else {
      setZoom(page.zoomBeforeFullScreen);
    }
    layout();
  });
  // The browser's zoom changes the window's size in CSS pixels, and says so by this event too.
  window.addEventListener("resize", layout);
  const state = await loadState();
  if (!state.scene.file) showDemos(true);
  await startRender();
  pollTiles();
  watchServer();
});
