// The docs site's code editor (CodeMirror 6), bundled by esbuild into one script that the site
// serves itself. live-canvas.js calls window.glintEditor.create when a page has a
// <div class="glint-edit">; without this script the code stays a plain, read-only block.
import { EditorState } from "@codemirror/state";
import {
  EditorView,
  keymap,
  lineNumbers,
  highlightActiveLine,
  highlightActiveLineGutter,
  drawSelection,
} from "@codemirror/view";
import { defaultKeymap, history, historyKeymap, indentWithTab } from "@codemirror/commands";
import {
  StreamLanguage,
  bracketMatching,
  defaultHighlightStyle,
  indentOnInput,
  syntaxHighlighting,
} from "@codemirror/language";
import { shader } from "@codemirror/legacy-modes/mode/clike";
import { lintGutter, setDiagnostics } from "@codemirror/lint";

const glsl = StreamLanguage.define(shader); // CodeMirror's GLSL (C-like) highlighting

// An editor in `parent` holding `doc`; `onChange(text)` runs after each edit, debounced by
// `delay` ms so that typing does not recompile on every key.
function create(parent, doc, onChange, delay = 400) {
  let timer = 0;
  const view = new EditorView({
    parent,
    state: EditorState.create({
      doc,
      extensions: [
        lineNumbers(),
        highlightActiveLineGutter(),
        highlightActiveLine(),
        drawSelection(),
        history(),
        indentOnInput(),
        bracketMatching(),
        glsl,
        syntaxHighlighting(defaultHighlightStyle, { fallback: true }),
        lintGutter(),
        EditorView.lineWrapping, // long comments wrap rather than scroll out of sight
        keymap.of([...defaultKeymap, ...historyKeymap, indentWithTab]),
        EditorView.updateListener.of((update) => {
          if (!update.docChanged) return;
          clearTimeout(timer);
          timer = setTimeout(() => onChange(view.state.doc.toString()), delay);
        }),
      ],
    }),
  });
  return {
    view,
    text: () => view.state.doc.toString(),
    // Replace the whole text, as a reset does (it also counts as an edit).
    setText: (text) =>
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text } }),
    // Compile errors at their lines: [{ line (1-based, in this text), message }].
    showErrors: (errors) => {
      const doc = view.state.doc;
      const diagnostics = errors.map((error) => {
        const line = doc.line(Math.min(Math.max(error.line, 1), doc.lines));
        return { from: line.from, to: line.to, severity: "error", message: error.message };
      });
      view.dispatch(setDiagnostics(view.state, diagnostics));
    },
  };
}

window.glintEditor = { create };
