// The interactive part of a model comparison page (comparison_html.cpp embeds this file and
// Chart.js into the page it writes). The page's data is the JSON of <script id="comparison-data">.
// Figures: drag a box to zoom, shift-drag to pan, the wheel zooms around the cursor, a double
// click resets; a legend entry shows or hides that curve in every figure; hovering shows values.
// The table sorts by a column when its header is clicked. With "#selftest" in the address the
// page exercises itself and writes what it saw into <pre id="selftest"> (the Chromium test).
"use strict";
(function () {
  const log = document.getElementById("page-errors");
  const report = (text) => {
    log.hidden = false;
    log.textContent += text + "\n";
  };
  window.addEventListener("error", (event) => report(`error: ${event.message}`));
  if (typeof Chart === "undefined") {
    report("error: the plotting library did not load");
    return;
  }

  const data = JSON.parse(document.getElementById("comparison-data").textContent);
  // Twenty colours (none black or grey: the measurement is black) and four dashes: model k gets
  // colour k and dash k mod 4, so no two of the first twenty look alike and neighbours in the
  // ranking differ in both.
  const palette = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2",
    "#17becf", "#bcbd22", "#393b79", "#aec7e8", "#ff9896", "#98df8a", "#c5b0d5", "#ffbb78",
    "#c49c94", "#f7b6d2", "#9edae5", "#dbdb8d", "#637939"];
  const dashes = [[], [6, 3], [2, 2], [8, 3, 2, 3]];
  const measuredColor = "#000000";
  // The figures over time use the record's time [s] where it has one, else the sample number.
  const timed = Array.isArray(data.time);
  const along = timed ? data.time : data.sample;
  const alongLabel = timed ? "time [s]" : "sample";
  const heldOut = timed ? data.validation_begin_time : data.validation_begin;
  const errorLabel = data.output_unit ? `error [${data.output_unit}]` : "error";
  const format = (value) => Number(value).toPrecision(5);
  const charts = [];

  // The held-out samples (x >= the first held-out sample's time or number), shaded behind the
  // curves.
  const shading = {
    id: "heldOutShading",
    beforeDatasetsDraw(chart) {
      if (!chart.options.plugins.heldOutShading.enabled) return;
      const area = chart.chartArea;
      const left = Math.max(chart.scales.x.getPixelForValue(heldOut), area.left);
      if (left >= area.right) return;
      const context = chart.ctx;
      context.save();
      context.fillStyle = "rgba(0, 0, 0, 0.07)";
      context.fillRect(left, area.top, area.right - left, area.bottom - area.top);
      context.fillStyle = "#555555";
      context.fillText("held out", left + 4, area.top + 12);
      context.restore();
    },
  };

  function points(xs, ys) {
    return xs.map((x, k) => ({ x, y: ys[k] }));
  }

  // A loop: the fit part faded, the held-out part in full colour (its points come in order, so
  // the line goes back and forth with the input as measured).
  // The first dataset is drawn last (Chart.js draws in reverse order): the measurement, first in
  // every figure, lies on top.
  function curve(label, xs, ys, style, fadeFitPart) {
    const color = style.color;
    const set = { label, data: points(xs, ys), borderColor: color, backgroundColor: color,
      borderDash: style.dash, hidden: style.hidden, showLine: true, pointRadius: 0,
      pointHitRadius: 4, borderWidth: style.width };
    if (fadeFitPart) {
      set.segment = { borderColor: (context) =>
        data.sample[context.p1DataIndex] <= data.validation_begin ? color + "40" : color };
    }
    return set;
  }

  function setVisibility(label, visible) {
    for (const chart of charts) {
      chart.data.datasets.forEach((set, k) => {
        if (set.label === label) chart.setDatasetVisibility(k, visible);
      });
      chart.update("none");
    }
  }

  function isVisible(label) {
    for (const chart of charts) {
      const k = chart.data.datasets.findIndex((set) => set.label === label);
      if (k >= 0) return chart.isDatasetVisible(k);
    }
    return false;
  }

  function toggle(label) {
    setVisibility(label, !isVisible(label));
  }

  function addZoom(chart) {
    const canvas = chart.canvas;
    const box = document.createElement("div");
    box.className = "zoom-box";
    canvas.parentElement.appendChild(box);
    let drag = null;
    const value = (axis, pixel) => chart.scales[axis].getValueForPixel(pixel);
    const setRange = (axis, min, max) => {
      chart.options.scales[axis].min = Math.min(min, max);
      chart.options.scales[axis].max = Math.max(min, max);
    };
    canvas.addEventListener("mousedown", (event) => {
      drag = { x: event.offsetX, y: event.offsetY, pan: event.shiftKey,
        range: { x: [chart.scales.x.min, chart.scales.x.max],
          y: [chart.scales.y.min, chart.scales.y.max] } };
    });
    canvas.addEventListener("mousemove", (event) => {
      if (!drag) return;
      if (drag.pan) {
        for (const axis of ["x", "y"]) {
          const shift = value(axis, axis === "x" ? drag.x : drag.y) -
            value(axis, axis === "x" ? event.offsetX : event.offsetY);
          setRange(axis, drag.range[axis][0] + shift, drag.range[axis][1] + shift);
        }
        chart.update("none");
        return;
      }
      Object.assign(box.style, { display: "block", left: `${Math.min(drag.x, event.offsetX)}px`,
        top: `${Math.min(drag.y, event.offsetY)}px`, width: `${Math.abs(event.offsetX - drag.x)}px`,
        height: `${Math.abs(event.offsetY - drag.y)}px` });
    });
    canvas.addEventListener("mouseup", (event) => {
      if (drag && !drag.pan && Math.abs(event.offsetX - drag.x) > 4 &&
          Math.abs(event.offsetY - drag.y) > 4) {
        setRange("x", value("x", drag.x), value("x", event.offsetX));
        setRange("y", value("y", drag.y), value("y", event.offsetY));
        chart.update("none");
      }
      box.style.display = "none";
      drag = null;
    });
    canvas.addEventListener("dblclick", () => {
      for (const axis of ["x", "y"]) {
        delete chart.options.scales[axis].min;
        delete chart.options.scales[axis].max;
      }
      chart.update("none");
    });
    canvas.addEventListener("wheel", (event) => {
      event.preventDefault();
      const factor = event.deltaY < 0 ? 0.8 : 1.25;
      const centre = value("x", event.offsetX);
      setRange("x", centre + (chart.scales.x.min - centre) * factor,
        centre + (chart.scales.x.max - centre) * factor);
      chart.update("none");
    }, { passive: false });
  }

  function figure(id, xLabel, yLabel, datasets, shaded) {
    const canvas = document.querySelector(`#${id} canvas`);
    const chart = new Chart(canvas, {
      type: "scatter",
      data: { datasets },
      plugins: [shading],
      options: {
        animation: false,
        maintainAspectRatio: false,
        interaction: { mode: "nearest", intersect: false },
        plugins: {
          heldOutShading: { enabled: shaded },
          legend: { position: "top", onClick: (event, item) => toggle(item.text) },
          tooltip: { callbacks: { label: (context) =>
            `${context.dataset.label}: ${xLabel} ${format(context.parsed.x)}, ` +
            `${yLabel} ${format(context.parsed.y)}` } },
        },
        scales: {
          x: { type: "linear", title: { display: true, text: xLabel } },
          y: { type: "linear", title: { display: true, text: yLabel } },
        },
      },
    });
    addZoom(chart);
    charts.push(chart);
  }

  const measured = { color: measuredColor, dash: [], hidden: false, width: 2 };
  // The models in ranking order; the best `data.shown` visible when the page opens.
  const models = data.models.map((model, k) => ({ ...model, style: {
    color: palette[k % palette.length], dash: dashes[k % dashes.length],
    hidden: k >= data.shown, width: 1.4 } }));
  figure("loops", data.input_label, data.output_label,
    [curve("measured", data.input, data.measured, measured, true)].concat(
      models.map((m) => curve(m.name, data.input, m.simulated, m.style, true))), false);
  figure("outputs", alongLabel, data.output_label,
    [curve("measured", along, data.measured, measured, false)].concat(
      models.map((m) => curve(m.name, along, m.simulated, m.style, false))), true);
  figure("errors", alongLabel, errorLabel,
    models.map((m) => curve(m.name, along, data.measured.map((y, k) => y - m.simulated[k]),
      m.style, false)), true);

  // The ranking table sorts by the clicked column (numbers as numbers; failed rows stay last).
  const table = document.getElementById("ranking");
  table.querySelectorAll("thead th").forEach((header, column) => {
    header.addEventListener("click", () => {
      const ascending = header.dataset.order !== "ascending";
      table.querySelectorAll("thead th").forEach((other) => delete other.dataset.order);
      header.dataset.order = ascending ? "ascending" : "descending";
      const body = table.tBodies[0];
      const rows = Array.from(body.rows);
      const key = (row) => {
        const text = row.cells[column] ? row.cells[column].textContent : "";
        const number = Number(text);
        return text !== "" && !Number.isNaN(number) ? number : text;
      };
      rows.sort((a, b) => {
        if (a.classList.contains("failed") !== b.classList.contains("failed")) {
          return a.classList.contains("failed") ? 1 : -1;
        }
        const p = key(a);
        const q = key(b);
        const order = typeof p === "number" && typeof q === "number" ? p - q
          : String(p).localeCompare(String(q));
        return ascending ? order : -order;
      });
      rows.forEach((row) => body.appendChild(row));
    });
  });

  if (window.location.hash === "#selftest") {
    const visible = () => charts.map((chart) =>
      chart.data.datasets.filter((set, k) => chart.isDatasetVisible(k)).length);
    const first = models.length ? models[0].name : "measured";
    const result = { figures: charts.length, before: visible() };
    result.hidden_at_open = charts.length ? charts[0].data.datasets.filter((set, k) =>
      !charts[0].isDatasetVisible(k)).length : 0;
    // What the figures look like: each model's colour and dash (distinct pairs), the measurement
    // first (on top) in black, the axes' titles, and any title longer than its axis (clipped).
    const styles = models.map((m) => `${m.style.color} ${m.style.dash.join(",")}`);
    result.distinct_styles = new Set(styles).size === styles.length;
    result.measured_on_top = charts.slice(0, 2).every((chart) =>
      chart.data.datasets[0].label === "measured" &&
      chart.data.datasets[0].borderColor === measuredColor);
    result.axes = charts.map((chart) =>
      [chart.options.scales.x.title.text, chart.options.scales.y.title.text]);
    result.clipped = [];
    for (const chart of charts) {
      for (const axis of ["x", "y"]) {
        const scale = chart.scales[axis];
        const font = Chart.helpers.toFont(scale.options.title.font);
        chart.ctx.save();
        chart.ctx.font = font.string;
        const width = chart.ctx.measureText(scale.options.title.text).width;
        chart.ctx.restore();
        const room = axis === "x" ? chart.width : chart.height;
        if (width > room) result.clipped.push(scale.options.title.text);
      }
    }
    result.chart_width = charts.length ? charts[0].width : 0;
    toggle(first);
    result.hidden = first;
    result.after = visible();
    toggle(first);
    result.restored = visible();
    const modelHeader = table.querySelectorAll("thead th")[1];
    modelHeader.click();
    modelHeader.click();
    result.sorted_descending_first = table.tBodies[0].rows[0].cells[1].textContent;
    result.errors = log.textContent;
    document.getElementById("selftest").textContent = JSON.stringify(result);
  }
})();
