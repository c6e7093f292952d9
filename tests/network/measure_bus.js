// Run in a bus picture by test_bus_picture.py: each row's producer dot and arrowheads against the lifelines of
// the nodes it names, and texts that overlap or leave the picture.
(() => {
  const meet = (a, b) => a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5;
  const svg = document.querySelector("svg").getBoundingClientRect();
  const lifeline = {};
  for (const line of document.querySelectorAll("line.lifeline")) lifeline[line.dataset.node] = line.getBoundingClientRect().left + line.getBoundingClientRect().width / 2;
  const rows = [...document.querySelectorAll("g.row")].map(row => {
    const dot = row.querySelector("circle.dot").getBoundingClientRect();
    const heads = [...row.querySelectorAll("path.head")].map(h => h.getBoundingClientRect());
    const consumers = row.dataset.consumers ? row.dataset.consumers.split(" ") : [];
    return {
      id: row.dataset.canId, producer: row.dataset.producer, consumers,
      dotOnProducer: Math.abs(dot.left + dot.width / 2 - lifeline[row.dataset.producer]) < 1,
      headsOnConsumers: consumers.every(name => heads.some(h => Math.abs(h.left - lifeline[name]) < 1 || Math.abs(h.right - lifeline[name]) < 1)),
      heads: heads.length,
    };
  });
  const texts = [...document.querySelectorAll("text")].map(t => ({text: t.textContent, box: t.getBoundingClientRect()}));
  const overlaps = [];
  for (let i = 0; i < texts.length; i++)
    for (let j = i + 1; j < texts.length; j++)
      if (meet(texts[i].box, texts[j].box)) overlaps.push([texts[i].text, texts[j].text]);
  const outside = texts.filter(t => t.box.right > svg.right + 0.5 || t.box.left < svg.left - 0.5).map(t => t.text);
  return {rows, overlaps, outside, nodes: Object.keys(lifeline)};
})()
