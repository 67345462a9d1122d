// Loaded between RequireJS and the ipywidgets HTML manager (nb_ipywidgets_js in _config.yml).
(function () {
  // 1. The manager finds its fonts next to the AMD module it defines,
  // "@jupyter-widgets/html-manager/dist/libembed-amd", which RequireJS would look up beside
  // the page; point that name at the copy in _static/vendor, found from this script's own
  // address, so that it works at every depth of the book, served or opened as a file.
  // Some widget views (the explorers' controls) inject the manager's Font Awesome styles a
  // second time with "@jupyter-widgets/<font file>" as the address: map that prefix to the
  // same folder, which holds the font files too.
  var here = document.currentScript.src;
  var vendor = here.slice(0, here.lastIndexOf("/") + 1) + "vendor/html-manager";
  require.config({
    paths: { "@jupyter-widgets/html-manager/dist": vendor, "@jupyter-widgets": vendor },
  });

  // 2. The manager typesets widget labels with MathJax 2's MathJax.Hub.Queue; the book loads
  // MathJax 3, which has no Hub. Give every object that becomes window.MathJax (first the
  // configuration, then MathJax itself) a Hub whose Queue calls MathJax 3's typesetPromise.
  var tries = 0;
  function typeset(element) {
    var mathjax = current;
    if (!mathjax || !mathjax.startup || !mathjax.startup.promise) {
      if (tries++ < 100) setTimeout(function () { typeset(element); }, 100);
      return;
    }
    mathjax.startup.promise
      .then(function () { return mathjax.typesetPromise(element ? [element] : undefined); })
      .catch(function (error) { console.warn("MathJax could not typeset a widget label", error); });
  }
  var hub = { Queue: function (job) { typeset(job && job[2]); } };
  function withHub(value) {
    if (value && typeof value === "object" && !value.Hub) value.Hub = hub;
    return value;
  }
  var current = withHub(window.MathJax);
  try {
    Object.defineProperty(window, "MathJax", {
      configurable: true,
      enumerable: true,
      get: function () { return current; },
      set: function (value) { current = withHub(value); },
    });
  } catch (error) {
    console.warn("widget labels will not be typeset:", error);
  }
})();
