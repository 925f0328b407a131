// gallery.css: layout of the index grid, the comparison viewer and the tables.
#include "gallery/assets/gallery_assets.h"

namespace vct {

const char* galleryCss() {
    return R"CSS(/* vct gallery */
:root { --fg: #1b1b1b; --muted: #666; --line: #d0d0d0; --accent: #1f5fbf; --bg: #fafafa; }
* { box-sizing: border-box; }
body { margin: 0 auto; padding: 12px 20px 40px; max-width: 1500px; font: 14px/1.45 system-ui, sans-serif;
       color: var(--fg); background: var(--bg); }
h1 { font-size: 22px; margin: 6px 0; }
h2 { font-size: 17px; margin: 22px 0 8px; border-bottom: 1px solid var(--line); padding-bottom: 3px; }
h3 { font-size: 15px; margin: 14px 0 6px; }
a { color: var(--accent); }
code { font-size: 12.5px; background: #eee; padding: 0 3px; border-radius: 3px; }
.small, figcaption { color: var(--muted); font-size: 12.5px; }
nav { font-size: 13px; }
button { font: inherit; padding: 2px 9px; border: 1px solid #aaa; background: #fff; border-radius: 4px; cursor: pointer; }
button.active { background: var(--accent); color: #fff; border-color: var(--accent); }
img.px, .thumb img, .tile img { image-rendering: pixelated; image-rendering: crisp-edges; }

/* index grid */
.sortbar { margin: 6px 0 10px; }
.grid-wrap { overflow-x: auto; }
table.grid { border-collapse: collapse; }
table.grid th, table.grid td { border: 1px solid var(--line); padding: 6px; vertical-align: top; text-align: center; background: #fff; }
table.grid thead th { background: #f0f0f0; font-weight: 600; }
table.grid .scene-col { text-align: left; min-width: 170px; }
.thumb img { display: block; width: 160px; height: auto; margin: 3px auto; border: 1px solid #ccc; }
.nums span { display: block; font-variant-numeric: tabular-nums; font-size: 12.5px; }
.nums .best { font-weight: 700; color: #0a7a2f; }
.nums .roi { color: #8a5a00; }
.na { color: #aaa; }

/* tables */
table.records { border-collapse: collapse; width: 100%; background: #fff; font-size: 13px; }
table.records th, table.records td { border: 1px solid var(--line); padding: 3px 6px; text-align: left; vertical-align: top; }
table.records th { background: #f0f0f0; }
table.sortable th { cursor: pointer; user-select: none; }
table.sortable th.sorted-asc::after { content: " \25B2"; }
table.sortable th.sorted-desc::after { content: " \25BC"; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.passes { font-size: 12px; color: var(--muted); }
table.kv { border-collapse: collapse; background: #fff; }
table.kv th, table.kv td { border: 1px solid var(--line); padding: 3px 8px; text-align: left; vertical-align: top; }
table.kv th { background: #f0f0f0; white-space: nowrap; }

/* comparison viewer */
.controls { display: flex; flex-wrap: wrap; gap: 8px 14px; align-items: center; margin-bottom: 6px; }
.controls .group button { margin-right: 2px; }
.readout { font-variant-numeric: tabular-nums; color: var(--muted); font-size: 12.5px; }
#slider-range { width: min(100%, 640px, calc(50% - 8px)); display: block; margin: 2px 0 6px; }
.views { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; }
.view-fig { margin: 0; flex: 1 1 360px; max-width: 640px; }
.viewport { position: relative; width: 100%; overflow: hidden; background: #222; cursor: grab; touch-action: none;
            border: 1px solid #555; user-select: none; }
.viewport.dragging { cursor: grabbing; }
.layer { position: absolute; inset: 0; overflow: hidden; pointer-events: none; }
.layer img.px { position: absolute; left: 0; top: 0; transform-origin: 0 0; max-width: none; }
.layer[hidden] { display: none; }
.split { position: absolute; top: 0; bottom: 0; width: 0; border-left: 2px solid #fff; box-shadow: 0 0 3px #000;
         cursor: ew-resize; }
.split::before { content: ""; position: absolute; top: 0; bottom: 0; left: -9px; width: 16px; }
.split .knob { position: absolute; top: 50%; left: -9px; width: 16px; height: 28px; margin-top: -14px; background: #fff;
               border-radius: 4px; box-shadow: 0 0 3px #000; }
.split[hidden] { display: none; }
.tag { position: absolute; top: 6px; padding: 1px 6px; background: rgba(0,0,0,.65); color: #fff; font-size: 12px;
       border-radius: 3px; pointer-events: none; max-width: 45%; overflow: hidden; text-overflow: ellipsis; white-space: nowrap; }
.tag-a { left: 6px; }
.tag-b { right: 6px; }
.legend { width: 256px; margin: 6px 0 4px; }
.legend img { display: block; width: 256px; height: 14px; }
.legend-labels { display: flex; justify-content: space-between; font-size: 12px; color: var(--fg); }

/* plots and tiles */
.plot-row { display: flex; flex-wrap: wrap; gap: 16px; }
.plot-row figure { margin: 0; background: #fff; border: 1px solid var(--line); padding: 4px; }
svg.plot { display: block; font-family: system-ui, sans-serif; }
svg.plot circle { cursor: pointer; }
svg.plot a:hover circle { stroke: #000; stroke-width: 2; }
.tiles { display: flex; flex-wrap: wrap; gap: 12px; }
.tile { margin: 0; text-align: center; }
.tile img { display: block; width: 160px; height: auto; border: 1px solid #ccc; }

footer.meta { margin-top: 30px; border-top: 1px solid var(--line); font-size: 13px; }
ul.credits, ul.downloads { padding-left: 20px; }
)CSS";
}

}  // namespace vct
