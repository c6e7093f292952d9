// Run in a page by test_pictures.py (check_pictures): for every PDO picture, the bits each field's rectangles
// cover (by the cells under them), rectangles that cover part of a cell, the fields labelled inside the grid and
// in the legend, texts that overlap, and labels that stick out of their field.
(() => {
  const inside = (a, b) => a.left >= b.left - 0.5 && a.right <= b.right + 0.5 && a.top >= b.top - 0.5 && a.bottom <= b.bottom + 0.5;
  const meet = (a, b) => a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5;
  const found = {};
  for (const group of document.querySelectorAll("g.pdo")) {
    const cells = [...group.querySelectorAll("rect.cell")].map(r => ({bit: +r.dataset.bit, box: r.getBoundingClientRect()}));
    const width = cells.length ? cells[0].box.width : 0;
    const fields = {}, partial = [], rects = {};
    for (const rect of group.querySelectorAll("rect.field")) {
      const box = rect.getBoundingClientRect(), number = rect.dataset.number;
      const covered = cells.filter(c => inside(c.box, box)).map(c => c.bit);
      if (Math.abs(box.width - covered.length * width) > 0.5) partial.push(number);
      (fields[number] = fields[number] || []).push(...covered);
      (rects[number] = rects[number] || []).push(box);
    }
    const texts = [...group.querySelectorAll("text")].map(t => ({css: t.getAttribute("class"), number: t.dataset.number, text: t.textContent, box: t.getBoundingClientRect()}));
    const overlaps = [];
    for (let i = 0; i < texts.length; i++)
      for (let j = i + 1; j < texts.length; j++)
        if (texts[i].text.trim() && texts[j].text.trim() && meet(texts[i].box, texts[j].box)) overlaps.push([texts[i].text, texts[j].text]);
    const stray = texts.filter(t => (t.css === "label" || t.css === "detail") && !(rects[t.number] || []).some(r => inside(t.box, r))).map(t => t.text);
    found[group.dataset.pdo] = {fields, partial, overlaps, stray,
      labelled: texts.filter(t => t.css === "label").map(t => t.number),
      legend: texts.filter(t => t.css === "legend").map(t => t.number)};
  }
  return found;
})()
