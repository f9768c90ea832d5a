// The catalog index as cards with filters. The page holds a plain table (the fallback without
// JavaScript) after an empty <div id="glint-catalog-filter">; this script turns its rows into
// cards and adds a slot selector and a text filter. It builds every element with the DOM API
// and copies the table's own links and images: no page text is ever parsed as HTML.
// Material's document$ emits on every page load, instant navigation included.
(function () {
  function setUp() {
    var marker = document.getElementById("glint-catalog-filter");
    if (!marker || marker.dataset.ready) return;
    var table = null;
    document.querySelectorAll("article table").forEach(function (t) {
      var after = marker.compareDocumentPosition(t) & Node.DOCUMENT_POSITION_FOLLOWING;
      if (!table && after) table = t;
    });
    if (!table) return;
    marker.dataset.ready = "1";
    var header = Array.from(table.querySelectorAll("thead th")).map(function (th) {
      return th.textContent.trim();
    });
    var column = function (name) { return header.indexOf(name); };
    var grid = document.createElement("div");
    grid.className = "glint-cards";
    var slots = [];
    var cards = Array.from(table.querySelectorAll("tbody tr")).map(function (row) {
      var cells = row.children;
      var card = document.createElement("div");
      card.className = "glint-card";
      var image = cells[column("picture")] && cells[column("picture")].querySelector("img");
      if (image) card.appendChild(image.cloneNode(true));
      var title = document.createElement("div");
      title.className = "glint-card-title";
      title.appendChild(cells[column("id")].firstElementChild.cloneNode(true));
      card.appendChild(title);
      var slot = cells[column("slot")].textContent.trim();
      if (slots.indexOf(slot) < 0) slots.push(slot);
      var meta = document.createElement("div");
      meta.className = "glint-card-meta";
      meta.appendChild(cells[column("slot")].firstElementChild.cloneNode(true));
      var front = cells[column("front")].textContent.trim();
      if (front) {
        var badge = document.createElement("span");
        badge.className = "glint-front";
        badge.textContent = "★ front";
        badge.title = "on its slot's cost/error front";
        meta.appendChild(badge);
      }
      card.appendChild(meta);
      var summary = document.createElement("p");
      summary.textContent = cells[column("summary")].textContent.trim();
      card.appendChild(summary);
      var rms = cells[column("RMS error")].textContent.trim();
      var ns = cells[column("ns per call")].textContent.trim();
      if (rms || ns) {
        var numbers = document.createElement("div");
        numbers.className = "glint-card-numbers";
        numbers.textContent = "RMS error " + (rms || "–") + " · " + (ns || "–") + " ns per call";
        card.appendChild(numbers);
      }
      card.dataset.slot = slot;
      card.dataset.text = row.textContent.toLowerCase();
      grid.appendChild(card);
      return card;
    });

    var controls = document.createElement("div");
    controls.className = "glint-filter";
    var select = document.createElement("select");
    select.setAttribute("aria-label", "slot");
    [""].concat(slots).forEach(function (slot) {
      var option = document.createElement("option");
      option.value = slot;
      option.textContent = slot ? "slot " + slot : "every slot";
      select.appendChild(option);
    });
    var search = document.createElement("input");
    search.type = "search";
    search.placeholder = "filter by text";
    search.setAttribute("aria-label", "filter by text");
    var count = document.createElement("span");
    count.className = "glint-count";
    function apply() {
      var words = search.value.toLowerCase().split(/\s+/).filter(Boolean);
      var shown = 0;
      cards.forEach(function (card) {
        var ok = (!select.value || card.dataset.slot === select.value) &&
          words.every(function (w) { return card.dataset.text.indexOf(w) >= 0; });
        card.hidden = !ok;
        if (ok) shown += 1;
      });
      count.textContent = shown + " of " + cards.length + " variants";
    }
    select.addEventListener("change", apply);
    search.addEventListener("input", apply);
    controls.append(select, search, count);
    marker.append(controls, grid);
    marker.hidden = false;
    var wrapper = table.closest(".md-typeset__scrollwrap") || table;
    wrapper.hidden = true;
    apply();
  }
  if (typeof document$ !== "undefined") {
    document$.subscribe(setUp);
  } else {
    document.addEventListener("DOMContentLoaded", setUp);
  }
})();
