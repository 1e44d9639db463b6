// The panes to the right of the editor (Picture, Player, Seeds, Infer): one
// shown at a time, chosen by tab buttons `#mode-NAME` that show
// `#NAME-pane`. `onOpen[NAME](first)` runs each time a pane is opened.
export function createTabs(onOpen) {
  const names = Object.keys(onOpen), opened = new Set(["picture"]);
  let current = "picture";
  const tab = (name) => document.getElementById("mode-" + name);
  function open(name) {
    current = name;
    for (const n of names) {
      tab(n).setAttribute("aria-selected", String(n === name));
      document.getElementById(n + "-pane").hidden = n !== name;
    }
    const first = !opened.has(name);
    opened.add(name);
    onOpen[name](first);
  }
  for (const n of names) tab(n).addEventListener("click", () => open(n));
  return { open, current: () => current };
}
