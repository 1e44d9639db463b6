// Highlighting for g2d in CodeMirror: a stream tokenizer whose word lists are
// read from the VS Code extension's TextMate grammar (one list of keywords,
// built-ins and types for both editors).
import { StreamLanguage } from "@codemirror/language";
import grammar from "../../../editors/vscode/syntaxes/g2d.tmLanguage.json";

// The words of every `\b(?:a|b|c)\b` pattern, by its scope's first part.
function wordLists() {
  const lists = { keyword: new Set(), builtin: new Set(), type: new Set(), atom: new Set() };
  const scopeList = (name) =>
    name.startsWith("keyword.") ? lists.keyword : name.startsWith("support.function") ? lists.builtin :
    name.startsWith("support.type") ? lists.type : name.startsWith("constant.language") || name.startsWith("support.constant") ? lists.atom : null;
  const visit = (o) => {
    if (Array.isArray(o)) return o.forEach(visit);
    if (!o || typeof o !== "object") return;
    const words = typeof o.match === "string" && /^\\b\(\?:([A-Za-z0-9_|]+)\)\\b$/.exec(o.match);
    const list = words && o.name && scopeList(o.name);
    if (list) for (const w of words[1].split("|")) list.add(w);
    Object.values(o).forEach(visit);
  };
  visit(grammar);
  return lists;
}

const words = wordLists();

export const g2dLanguage = StreamLanguage.define({
  name: "g2d",
  startState: () => ({ inComment: false }),
  token(stream, state) {
    if (state.inComment) {
      if (stream.skipTo("*/")) stream.match("*/"), (state.inComment = false);
      else stream.skipToEnd();
      return "comment";
    }
    if (stream.eatSpace()) return null;
    if (stream.match("//")) return stream.skipToEnd(), "comment";
    if (stream.match("/*")) return (state.inComment = true), this.token(stream, state);
    if (stream.match(/^"(?:[^"\\]|\\.)*"?/)) return "string";
    if (stream.match(/^(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?/)) return "number";
    if (stream.match(/^[A-Za-z_][A-Za-z0-9_]*/)) {
      const w = stream.current();
      if (words.keyword.has(w)) return "keyword";
      if (words.atom.has(w)) return "atom";
      if (words.type.has(w)) return "typeName";
      if (stream.match(/^\s*\(/, false)) return words.builtin.has(w) ? "variableName.standard" : "variableName.function";
      return /^[A-Z]/.test(w) ? "className" : "variableName";
    }
    if (stream.match(/^(?:<-\[|-\[|\]->|\]-|->|==|!=|<=|>=|&&|\|\|)/)) return "operator";
    stream.next();
    return /[-+*/%<>=!@]/.test(stream.current()) ? "operator" : "punctuation";
  },
  languageData: { commentTokens: { line: "//", block: { open: "/*", close: "*/" } } },
});
