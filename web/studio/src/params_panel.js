// The parameters panel: a control per `param` declaration (a slider and a
// number field for an int or float with a range, a number field without
// one, a checkbox, a drop-down of an enum's values, a text field, a number
// field per component of a vector), each labelled with the parameter's
// name; then the seed (with "Another seed") and the step limit. Values the
// user has not touched stay the grammar's defaults, so editing a default in
// the text shows at once.
const el = (tag, props = {}, ...children) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
};

// What makes two spec lists need different controls.
const shape = (specs) => JSON.stringify(specs.map((p) => [p.name, p.type, p.values, p.min, p.max, p.step]));

export function createParamsPanel(root, onChange) {
  const set = new Map();   // name -> value the user chose
  let specs = [], drawnShape = null, defaults = new Map();
  const list = el("div", { id: "param-list" });
  const seed = el("input", { id: "seed", type: "number", min: 0, step: 1, value: 1 });
  const another = el("button", { id: "another-seed", type: "button", textContent: "Another seed" });
  const steps = el("input", { id: "steps", type: "number", min: 0, step: 1, placeholder: "the grammar's" });
  const reset = el("button", { id: "reset-params", type: "button", textContent: "Defaults" });
  root.append(
    list,
    el("div", { className: "run-settings" },
      el("label", { htmlFor: "seed", textContent: "Seed" }), seed, another,
      el("label", { htmlFor: "steps", textContent: "Step limit" }), steps, reset));
  another.addEventListener("click", () => ((seed.value = String(seedValue() + 1)), onChange()));
  seed.addEventListener("input", () => seed.validity.valid && seed.value !== "" && onChange());
  steps.addEventListener("input", () => steps.validity.valid && onChange());
  reset.addEventListener("click", () => (set.clear(), (drawnShape = null), draw(specs), onChange()));

  function seedValue() {
    const n = Number(seed.value);
    return Number.isSafeInteger(n) && n >= 0 ? n : 1;
  }

  function choose(name, value) {
    set.set(name, value);
    onChange();
  }

  function control(p) {
    const id = "param-" + p.name, value = set.has(p.name) ? set.get(p.name) : p.default;
    const label = el("label", { htmlFor: id, textContent: p.name, title: p.type_name });
    const row = el("div", { className: "param" });
    if (p.type === "int" || p.type === "float") {
      const step = p.step ?? (p.type === "int" ? 1 : "any");
      const number = el("input", { id, type: "number", step, value });
      if (p.min !== undefined) number.min = p.min;
      if (p.max !== undefined) number.max = p.max;
      const read = (text) => (p.type === "int" ? parseInt(text, 10) : parseFloat(text));
      number.addEventListener("input", () => {
        const v = read(number.value);
        if (Number.isFinite(v)) {
          if (slider) slider.value = v;
          choose(p.name, v);
        }
      });
      let slider = null;
      if (p.min !== undefined && p.max !== undefined) {
        // The slider is the same parameter's second control: named, but not by a second label.
        slider = el("input", { type: "range", min: p.min, max: p.max, step: p.step ?? (p.type === "int" ? 1 : (p.max - p.min) / 100), value });
        slider.setAttribute("aria-label", p.name);
        slider.addEventListener("input", () => ((number.value = slider.value), choose(p.name, read(slider.value))));
      }
      row.append(label, ...(slider ? [slider] : []), number);
    } else if (p.type === "bool") {
      const box = el("input", { id, type: "checkbox", checked: !!value });
      box.addEventListener("change", () => choose(p.name, box.checked));
      row.append(box, label);
    } else if (p.type === "enum") {
      const select = el("select", { id }, ...p.values.map((v) => el("option", { value: v, textContent: v, selected: v === value })));
      select.addEventListener("change", () => choose(p.name, select.value));
      row.append(label, select);
    } else if (p.type === "vec2" || p.type === "vec3") {
      const parts = p.type === "vec2" ? ["x", "y"] : ["x", "y", "z"];
      const fields = parts.map((axis, i) => {
        const f = el("input", { id: i === 0 ? id : `${id}-${axis}`, type: "number", step: "any", value: value[i] });
        f.setAttribute("aria-label", `${p.name} ${axis}`);
        return f;
      });
      const changed = () => {
        const v = fields.map((f) => parseFloat(f.value));
        if (v.every(Number.isFinite)) choose(p.name, v);
      };
      fields.forEach((f) => f.addEventListener("input", changed));
      row.append(label, ...fields);
    } else {
      const text = el("input", { id, type: "text", value });
      text.addEventListener("input", () => choose(p.name, text.value));
      row.append(label, text);
    }
    return row;
  }

  // Controls for `newSpecs`, made again only when the parameters changed;
  // a default edited in the text moves the controls the user did not touch.
  function draw(newSpecs) {
    specs = newSpecs || [];
    const names = new Set(specs.map((p) => p.name));
    for (const name of [...set.keys()]) if (!names.has(name)) set.delete(name);
    const s = shape(specs);
    const newDefaults = new Map(specs.map((p) => [p.name, JSON.stringify(p.default)]));
    const defaultsMoved = [...newDefaults].some(([n, d]) => !set.has(n) && defaults.get(n) !== d);
    defaults = newDefaults;
    if (s === drawnShape && !defaultsMoved) return;
    drawnShape = s;
    list.replaceChildren(...specs.map(control));
    if (!specs.length) list.append(el("p", { className: "empty", textContent: "No parameters (declare one with `param NAME: TYPE = DEFAULT;`)." }));
  }

  return {
    draw,
    // The run request's part: {"params", "seed", "steps"?}.
    request() {
      const out = { params: Object.fromEntries(set), seed: seedValue() };
      const n = Number(steps.value);
      if (steps.value !== "" && Number.isSafeInteger(n) && n >= 0) out.steps = n;
      return out;
    },
    setSeed(n) {
      seed.value = String(n);
      onChange();
    },
  };
}
