// Run in the HTML page by test_pictures.py: links to anchors that are not there, and what the filter box shows
// for an index, a name, a word no object has, and nothing.
(() => {
  const broken = [...document.querySelectorAll('a[href^="#"]')].map(a => a.getAttribute("href").slice(1)).filter(id => !document.getElementById(id));
  const box = document.getElementById("filter");
  const shown = text => { box.value = text; box.dispatchEvent(new Event("input")); return [...document.querySelectorAll("section.object")].filter(s => s.getBoundingClientRect().height > 0).map(s => s.id); };
  const result = {broken, byIndex: shown("1a00"), byName: shown("statusword"), none: shown("no such object at all"), all: shown("")};
  return result;
})()
