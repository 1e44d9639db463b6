// The grammar's editor: CodeMirror 6 with g2d's highlighting, the checker's
// diagnostics at their lines (@codemirror/lint), and the language server's
// completion.
import { autocompletion } from "@codemirror/autocomplete";
import { defaultKeymap, history, historyKeymap, indentWithTab } from "@codemirror/commands";
import { bracketMatching, defaultHighlightStyle, indentOnInput, syntaxHighlighting } from "@codemirror/language";
import { forEachDiagnostic, lintGutter, setDiagnostics } from "@codemirror/lint";
import { highlightSelectionMatches, searchKeymap } from "@codemirror/search";
import { Annotation, EditorState } from "@codemirror/state";
import { EditorView, drawSelection, highlightActiveLine, keymap, lineNumbers } from "@codemirror/view";
import { g2dLanguage } from "./g2d_language.js";

// Marks a change made from the file on disk: not an edit of the user's.
const fromFile = Annotation.define();

// The LSP's CompletionItemKind as CodeMirror's icon names.
const KINDS = { 3: "function", 6: "variable", 7: "class", 10: "property", 13: "enum", 14: "keyword", 20: "enum", 21: "constant", 22: "type" };

// Completion from the language server's list (`complete(text, line, character)`, the studio's
// /api/complete): names in scope, attributes after `x.`, built-ins and keywords.
function serverCompletions(complete) {
  return async (context) => {
    const word = context.matchBefore(/[A-Za-z_][A-Za-z0-9_]*/), dot = context.matchBefore(/\.$/);
    if (!context.explicit && !dot && (!word || word.from === word.to)) return null;
    const line = context.state.doc.lineAt(context.pos);
    const items = await complete(context.state.doc.toString(), line.number, context.pos - line.from);
    if (context.aborted || !items) return null;
    return {
      from: word ? word.from : context.pos,
      options: items.map((i) => ({ label: i.label, type: KINDS[i.kind] || "text", detail: i.detail })),
      validFor: /^[A-Za-z_][A-Za-z0-9_]*$/,
    };
  };
}

// An editor in `parent`. `onEdit(text)` is called after every change of the text.
export function createEditor(parent, { onEdit, onSave, complete }) {
  const view = new EditorView({
    parent,
    state: EditorState.create({
      doc: "",
      extensions: [
        lineNumbers(), history(), drawSelection(), highlightActiveLine(), indentOnInput(), bracketMatching(),
        highlightSelectionMatches(), lintGutter(), g2dLanguage, syntaxHighlighting(defaultHighlightStyle),
        autocompletion({ override: [serverCompletions(complete)] }),
        keymap.of([{ key: "Mod-s", run: () => (onSave(), true), preventDefault: true },
                   indentWithTab, ...defaultKeymap, ...historyKeymap, ...searchKeymap]),
        EditorView.updateListener.of((u) => {
          if (u.docChanged && !u.transactions.every((t) => t.annotation(fromFile))) onEdit(view.state.doc.toString());
        }),
        EditorView.contentAttributes.of({ "aria-label": "Grammar" }),
      ],
    }),
  });

  // Diagnostics of `g2d check` (1-based lines and columns; `end_column` on
  // `end_line`) at their places; those of imported files are not in this text.
  function showDiagnostics(list, inThisText) {
    const doc = view.state.doc;
    const at = (line, column) => {
      if (!(line >= 1)) return 0;
      if (line > doc.lines) return doc.length;
      const l = doc.line(line);
      return Math.min(l.from + Math.max(column - 1, 0), l.to);
    };
    const marks = (list || []).filter(inThisText).map((d) => {
      const from = at(d.line, d.column);
      const to = Math.max(from, at(d.end_line || d.line, d.end_column || d.column));
      const notes = (d.notes || []).map((n) => "\n" + (n.message || n)).join("");
      return { from, to, severity: d.severity === "error" ? "error" : d.severity === "warning" ? "warning" : "info",
               message: d.message + notes };
    });
    view.dispatch(setDiagnostics(view.state, marks));
  }

  return {
    view,
    text: () => view.state.doc.toString(),
    setText(text) {
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text }, annotations: fromFile.of(true) });
    },
    showDiagnostics,
    // The marks shown, as [{line, severity, message}] (for tests).
    marks() {
      const out = [];
      forEachDiagnostic(view.state, (d, from) => out.push({ line: view.state.doc.lineAt(from).number, severity: d.severity, message: d.message }));
      return out;
    },
    // Selects the first `text` and focuses the editor, so that typing replaces it (for tests and the benchmark).
    select(text) {
      const at = view.state.doc.toString().indexOf(text);
      if (at < 0) return false;
      view.focus();
      view.dispatch({ selection: { anchor: at, head: at + text.length }, scrollIntoView: true });
      return true;
    },
  };
}
