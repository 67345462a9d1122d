/* Loaded on every page of the book (html_js_files in _config.yml).  On a page that holds a
 * static explorer ([data-vbi-explorer], written by vbi_lib.widgets.page) it loads, from the
 * book's own files: uPlot (vendor/uplot, from npm), the port of the crossing models
 * (vbi-model.js) and the explorers (vbi-explorers.js); elsewhere it does nothing. */
(function () {
  "use strict";
  var here = document.currentScript.src;
  var base = here.slice(0, here.lastIndexOf("/") + 1);
  function css(href) {
    var link = document.createElement("link");
    link.rel = "stylesheet";
    link.href = href;
    document.head.appendChild(link);
  }
  function script(src) {
    return new Promise(function (resolve, reject) {
      var element = document.createElement("script");
      element.src = src;
      element.onload = resolve;
      element.onerror = function () { reject(new Error("could not load " + src)); };
      document.head.appendChild(element);
    });
  }
  function start() {
    if (!document.querySelector("[data-vbi-explorer]")) return;
    css(base + "../vendor/uplot/uPlot.min.css");
    css(base + "vbi-explorers.css");
    script(base + "../vendor/uplot/uPlot.iife.min.js")
      .then(function () { return script(base + "vbi-model.js"); })
      .then(function () { return script(base + "vbi-explorers.js"); })
      .catch(function (error) {
        document.querySelectorAll("[data-vbi-explorer]").forEach(function (root) {
          var note = document.createElement("p");
          note.className = "vbi-notice";
          note.textContent = "The explorer could not start: " + error.message;
          root.appendChild(note);
        });
      });
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
