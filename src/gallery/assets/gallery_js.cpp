// gallery.js: the comparison viewer (slider/flip, synchronized pixel zoom and pan, ROI overlay,
// state in the URL hash), the index's column ordering and the sortable tables. Plain ES5-ish
// JavaScript: no framework, no network, works from file:// URLs.
#include "gallery/assets/gallery_assets.h"

namespace vct {

const char* galleryJs() {
    return R"JS(/* vct gallery */
(function () {
  'use strict';
  function $(id) { return document.getElementById(id); }
  function each(list, fn) { Array.prototype.forEach.call(list, fn); }
  function clamp(v, lo, hi) { return Math.min(hi, Math.max(lo, v)); }
  function numberOr(v, d) { var x = parseFloat(v); return isFinite(x) ? x : d; }

  // Errors also land in the DOM, so a test reading --dump-dom sees them.
  window.addEventListener('error', function (e) {
    if (document.body) document.body.setAttribute('data-js-errors',
      (document.body.getAttribute('data-js-errors') || '') + String(e.message) + '\n');
  });

  // "#a=x&b=y&slider=0.3" -> {a: 'x', b: 'y', slider: '0.3'}
  function parseHash() {
    var out = {};
    location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
      if (!kv) return;
      var i = kv.indexOf('=');
      var k = decodeURIComponent(i < 0 ? kv : kv.slice(0, i));
      out[k] = i < 0 ? '' : decodeURIComponent(kv.slice(i + 1));
    });
    return out;
  }

  // ---- tables sortable by a click on a header (data-type="num" sorts by td data-value)
  function makeSortable(table) {
    var ths = table.tHead.rows[0].cells;
    each(ths, function (th, col) {
      th.addEventListener('click', function () {
        var asc = !th.classList.contains('sorted-asc');
        each(ths, function (h) { h.classList.remove('sorted-asc', 'sorted-desc'); });
        th.classList.add(asc ? 'sorted-asc' : 'sorted-desc');
        var numeric = th.getAttribute('data-type') === 'num';
        var body = table.tBodies[0];
        var rows = Array.prototype.slice.call(body.rows);
        rows.sort(function (r1, r2) {
          var c1 = r1.cells[col], c2 = r2.cells[col];
          if (numeric) {
            var v1 = parseFloat(c1.getAttribute('data-value')), v2 = parseFloat(c2.getAttribute('data-value'));
            var n1 = isNaN(v1), n2 = isNaN(v2);
            if (n1 || n2) return n1 === n2 ? 0 : (n1 ? 1 : -1);  // missing values last
            return asc ? v1 - v2 : v2 - v1;
          }
          var t = c1.textContent.localeCompare(c2.textContent);
          return asc ? t : -t;
        });
        rows.forEach(function (r) { body.appendChild(r); });
      });
    });
  }

  // ---- index grid: order the method columns by run order, mean error rank or mean time rank
  function initGrid(grid) {
    var buttons = document.querySelectorAll('.sortbar button');
    function order(by) {
      var head = grid.tHead.rows[0];
      var ths = Array.prototype.slice.call(head.querySelectorAll('th[data-col]'));
      ths.sort(function (a, b) {
        return (numberOr(a.getAttribute('data-' + by), 0) - numberOr(b.getAttribute('data-' + by), 0)) ||
               (numberOr(a.getAttribute('data-run'), 0) - numberOr(b.getAttribute('data-run'), 0));
      });
      ths.forEach(function (th) { head.appendChild(th); });
      each(grid.tBodies[0].rows, function (row) {
        var byCol = {};
        each(row.querySelectorAll('td[data-col]'), function (td) { byCol[td.getAttribute('data-col')] = td; });
        ths.forEach(function (th) { var td = byCol[th.getAttribute('data-col')]; if (td) row.appendChild(td); });
      });
      each(buttons, function (b) { b.classList.toggle('active', b.getAttribute('data-order') === by); });
    }
    each(buttons, function (b) { b.addEventListener('click', function () { order(b.getAttribute('data-order')); }); });
    var h = parseHash();
    if (h.order === 'error' || h.order === 'time') order(h.order);
  }

  // ---- comparison viewer
  function initViewer() {
    var main = $('view-main');
    if (!main) return;
    var errView = $('view-error');
    var views = [main, errView].filter(Boolean);
    var W = numberOr(main.getAttribute('data-w'), 1), H = numberOr(main.getAttribute('data-h'), 1);
    var selA = $('sel-a'), selB = $('sel-b');
    // zoom: screen px per image px (0 = fit); (cx, cy): the image point at the centre of every view.
    var st = { split: 0.5, mode: 'slider', showB: false, roi: false, zoom: 0, cx: W / 2, cy: H / 2 };

    function fitZoom() { return Math.max(1e-3, Math.min(main.clientWidth / W, main.clientHeight / H)); }
    function zoom() { return st.zoom > 0 ? st.zoom : fitZoom(); }
    function option(sel, id) {
      for (var i = 0; i < sel.options.length; i++) if (sel.options[i].value === id) return sel.options[i];
      return null;
    }
    function setSrc(img, src) { if (img && src && img.getAttribute('src') !== src) img.setAttribute('src', src); }

    function setImages() {
      var a = option(selA, selA.value), b = option(selB, selB.value);
      if (a) { setSrc($('img-a'), a.getAttribute('data-src')); $('tag-a').textContent = 'A: ' + a.textContent; }
      if (b) { setSrc($('img-b'), b.getAttribute('data-src')); $('tag-b').textContent = 'B: ' + b.textContent; }
      // The error view shows B's error map, else A's.
      var e = [b, a].filter(function (o) { return o && o.getAttribute('data-error-src'); })[0];
      var img = $('img-err');
      if (!img) return;
      if (e) {
        setSrc(img, e.getAttribute('data-error-src'));
        img.hidden = false;
        var s = numberOr(e.getAttribute('data-error-scale'), NaN);
        var txt = isFinite(s) ? String(+s.toPrecision(4)) : '?';
        $('leg-lo').textContent = '\u2212' + txt;
        $('leg-hi').textContent = '+' + txt;
        $('err-title').textContent = e.getAttribute('data-group') === 'Error' ? e.textContent : e.textContent + ': error';
      } else {
        img.hidden = true;
        $('err-title').textContent = 'no error map for A or B';
      }
    }

    function layout() {
      var z = zoom();
      views.forEach(function (vp) {
        var tx = vp.clientWidth / 2 - st.cx * z, ty = vp.clientHeight / 2 - st.cy * z;
        each(vp.querySelectorAll('img.px'), function (img) {
          img.style.transform = 'translate(' + tx + 'px,' + ty + 'px) scale(' + z + ')';
        });
      });
      var layerB = $('layer-b'), split = $('split');
      if (st.mode === 'slider') {
        layerB.hidden = false;
        layerB.style.clipPath = 'inset(0 0 0 ' + (st.split * 100) + '%)';
        split.hidden = false;
        split.style.left = (st.split * 100) + '%';
        $('tag-a').hidden = st.split < 0.02;
        $('tag-b').hidden = st.split > 0.98;
      } else {
        layerB.style.clipPath = 'none';
        layerB.hidden = !st.showB;
        split.hidden = true;
        $('tag-a').hidden = st.showB;
        $('tag-b').hidden = !st.showB;
      }
      each(document.querySelectorAll('.roi-layer'), function (l) { l.hidden = !st.roi; });
      if ($('chk-roi')) $('chk-roi').checked = st.roi;
      $('slider-range').value = Math.round(st.split * 1000);
      $('slider-range').disabled = st.mode !== 'slider';
      $('btn-mode-slider').classList.toggle('active', st.mode === 'slider');
      $('btn-mode-flip').classList.toggle('active', st.mode === 'flip');
      $('zoom-readout').textContent = 'zoom ' + z.toFixed(2) + '\u00d7' + (st.zoom > 0 ? '' : ' (fit)');
    }

    var hashTimer = 0;
    function writeHash() {
      var parts = ['a=' + encodeURIComponent(selA.value), 'b=' + encodeURIComponent(selB.value),
                   'slider=' + st.split.toFixed(3), 'mode=' + st.mode];
      if (st.mode === 'flip') parts.push('flip=' + (st.showB ? 1 : 0));
      if (st.roi) parts.push('roi=1');
      if (st.zoom > 0) parts.push('zoom=' + st.zoom.toFixed(3), 'cx=' + st.cx.toFixed(2), 'cy=' + st.cy.toFixed(2));
      var h = '#' + parts.join('&');
      if (location.hash === h) return;
      try { history.replaceState(null, '', h); } catch (err) { /* some file:// setups refuse; state still works */ }
    }
    // Debounced: browsers throttle (and log about) rapid history updates during drags.
    function scheduleHash() { clearTimeout(hashTimer); hashTimer = setTimeout(writeHash, 300); }
    function update() { setImages(); layout(); scheduleHash(); }

    function applyHash(fromLink) {
      var h = parseHash();
      if (h.a && option(selA, h.a)) selA.value = h.a;
      if (h.b && option(selB, h.b)) {
        selB.value = h.b;
        if (!h.a) {  // a link naming only B: compare it with the reference of its kind
          var g = option(selB, h.b).getAttribute('data-group');
          var ref = g === 'Indirect' ? 'reference_gi' : g === 'Beauty' ? 'reference_beauty' : 'reference_ao';
          if (option(selA, ref)) selA.value = ref;
        }
      }
      if (h.slider !== undefined) st.split = clamp(numberOr(h.slider, 0.5), 0, 1);
      if (h.mode === 'flip' || h.mode === 'slider') st.mode = h.mode;
      if (h.flip !== undefined) st.showB = h.flip === '1' || h.flip === 'b';
      if (h.roi !== undefined) st.roi = h.roi === '1';
      if (h.zoom !== undefined) st.zoom = h.zoom === 'fit' ? 0 : Math.max(0, numberOr(h.zoom, 0));
      if (h.cx !== undefined) st.cx = numberOr(h.cx, W / 2);
      if (h.cy !== undefined) st.cy = numberOr(h.cy, H / 2);
      setImages();
      layout();
      if (fromLink && (h.a || h.b)) $('compare').scrollIntoView({ block: 'start' });
    }

    function fit() { st.zoom = 0; st.cx = W / 2; st.cy = H / 2; layout(); scheduleHash(); }
    function zoomAt(vp, factor, clientX, clientY) {
      var r = vp.getBoundingClientRect(), z = zoom();
      var mx = clientX - r.left - r.width / 2, my = clientY - r.top - r.height / 2;
      var px = st.cx + mx / z, py = st.cy + my / z;  // the image point under the cursor stays put
      var nz = clamp(z * factor, fitZoom() / 4, 256);
      st.zoom = nz;
      st.cx = px - mx / nz;
      st.cy = py - my / nz;
      layout();
      scheduleHash();
    }
    function zoomCentre(factor) { var r = main.getBoundingClientRect(); zoomAt(main, factor, r.left + r.width / 2, r.top + r.height / 2); }

    function readout(vp, ev) {
      var r = vp.getBoundingClientRect(), z = zoom();
      var x = Math.floor(st.cx + (ev.clientX - r.left - r.width / 2) / z);
      var y = Math.floor(st.cy + (ev.clientY - r.top - r.height / 2) / z);
      $('pixel-readout').textContent = (x >= 0 && y >= 0 && x < W && y < H) ? 'pixel (' + x + ', ' + y + ')' : '';
    }

    function attach(vp, withSplit) {
      var drag = null;
      vp.addEventListener('pointerdown', function (ev) {
        if (ev.button !== 0) return;
        var r = vp.getBoundingClientRect();
        if (withSplit && st.mode === 'slider' && Math.abs(ev.clientX - r.left - st.split * r.width) < 12) {
          drag = { split: true };
        } else {
          if (st.zoom === 0) st.zoom = fitZoom();  // panning leaves "fit"
          drag = { split: false, x: ev.clientX, y: ev.clientY, cx: st.cx, cy: st.cy };
        }
        vp.setPointerCapture(ev.pointerId);
        vp.classList.add('dragging');
        ev.preventDefault();
      });
      vp.addEventListener('pointermove', function (ev) {
        readout(vp, ev);
        if (!drag) return;
        var r = vp.getBoundingClientRect();
        if (drag.split) {
          st.split = clamp((ev.clientX - r.left) / r.width, 0, 1);
        } else {
          var z = zoom();
          st.cx = drag.cx - (ev.clientX - drag.x) / z;
          st.cy = drag.cy - (ev.clientY - drag.y) / z;
        }
        layout();
      });
      function end() { if (drag) { drag = null; vp.classList.remove('dragging'); scheduleHash(); } }
      vp.addEventListener('pointerup', end);
      vp.addEventListener('pointercancel', end);
      vp.addEventListener('pointerleave', function () { $('pixel-readout').textContent = ''; });
      vp.addEventListener('wheel', function (ev) {
        ev.preventDefault();
        zoomAt(vp, ev.deltaY < 0 ? Math.SQRT2 : Math.SQRT1_2, ev.clientX, ev.clientY);
      }, { passive: false });
      vp.addEventListener('dblclick', fit);
    }
    views.forEach(function (vp) { attach(vp, vp === main); });

    selA.addEventListener('change', update);
    selB.addEventListener('change', update);
    $('slider-range').addEventListener('input', function () {
      st.split = numberOr(this.value, 500) / 1000;
      layout();
      scheduleHash();
    });
    $('btn-mode-slider').addEventListener('click', function () { st.mode = 'slider'; layout(); scheduleHash(); });
    $('btn-mode-flip').addEventListener('click', function () { st.mode = 'flip'; layout(); scheduleHash(); });
    function flip() {
      if (st.mode !== 'flip') { st.mode = 'flip'; st.showB = true; } else st.showB = !st.showB;
      layout();
      scheduleHash();
    }
    $('btn-flip').addEventListener('click', flip);
    $('btn-fit').addEventListener('click', fit);
    $('btn-1x').addEventListener('click', function () { st.zoom = 1; layout(); scheduleHash(); });
    $('btn-zoom-in').addEventListener('click', function () { zoomCentre(2); });
    $('btn-zoom-out').addEventListener('click', function () { zoomCentre(0.5); });
    if ($('chk-roi')) $('chk-roi').addEventListener('change', function () { st.roi = this.checked; layout(); scheduleHash(); });
    document.addEventListener('keydown', function (ev) {
      var tag = ev.target && ev.target.tagName;
      if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA' || ev.ctrlKey || ev.metaKey || ev.altKey) return;
      var k = ev.key;
      if (k === 'f' || k === 'F') flip();
      else if (k === 's' || k === 'S') { st.mode = 'slider'; layout(); scheduleHash(); }
      else if ((k === 'r' || k === 'R') && $('chk-roi')) { st.roi = !st.roi; layout(); scheduleHash(); }
      else if (k === '0') fit();
      else if (k === '1') { st.zoom = 1; layout(); scheduleHash(); }
      else if (k === '+' || k === '=') zoomCentre(2);
      else if (k === '-') zoomCentre(0.5);
      else return;
      ev.preventDefault();
    });
    window.addEventListener('resize', layout);
    window.addEventListener('hashchange', function () { applyHash(true); });
    applyHash(false);
  }

  function init() {
    each(document.querySelectorAll('table.sortable'), makeSortable);
    if ($('grid')) initGrid($('grid'));
    initViewer();
    document.body.setAttribute('data-gallery-ready', '1');
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', init);
  else init();
})();
)JS";
}

}  // namespace vct
