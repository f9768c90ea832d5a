// Live WebGL2 canvases on glint's docs site.
//
// A page holds <canvas class="glint-live-canvas" data-shader="img/live/X.glsl" data-time="1">
// inside <div class="glint-live">; data-shader is relative to the site's root. The script fetches
// the shader (its text never goes into the HTML), compiles it (a complete `#version 300 es`
// shader as `glint compose --target webgl2` writes it, or ShaderToy Image-tab code, which it
// wraps in ShaderToy's uniforms and a main), and draws one frame at data-time. Play runs the
// clock; the time slider scrubs it; a mouse drag sets iMouse as ShaderToy does; each parameter
// of the shader's /* glint-params */ manifest gets a slider that sets its uniform; a vec3 gets
// a colour picker ("color": linear RGB, shown as sRGB) or azimuth and elevation sliders
// ("direction": a unit vector). A <select class="glint-live-choice"> beside the canvas swaps
// its shader for the chosen one (a slot's variants). Compile errors appear in a <pre> under
// the canvas.
//
// Chrome keeps only about 16 WebGL contexts alive at once and drops the oldest beyond that, so
// a page of many canvases manages its own: a canvas starts when scrolled into view; when more
// than MAX_CONTEXTS are alive, those out of view longest give theirs up (parked: their last
// frame stays as a picture) and get it back when scrolled into view again. A context the
// browser takes away (a GPU reset, its own limit) is restored the same way. Every context is
// given up when the page changes.
//
// A <div class="glint-compare"> holds two such canvases, A and B, stacked: B shows right of a
// divider the reader drags, and a checkbox shows |A - B| times a gain instead. A's controls
// drive both (time, mouse, the parameters both shaders have); B's are hidden.
//
// A <div class="glint-edit" data-shader="..." data-shadertoy="..."> holds a variant's code in a
// <pre>: the script loads the editor (assets/glint-editor.js, CodeMirror) in its place; an edit
// puts the new code where the old stood in the canvas's shader (the canvas whose data-shader is
// the same) and recompiles it, keeping its time, sliders and play; a compile error shows at its
// line in the editor. "Copy as ShaderToy" copies the data-shadertoy shader with the edit.
(function () {
  "use strict";

  // The site's root, from this script's own URL (assets/live-canvas.js): pages at any depth,
  // and pages reached by Material's instant navigation, resolve data-shader the same way.
  var ROOT = new URL("../", document.currentScript.src);

  var VERTEX =
    "#version 300 es\n" +
    "void main() {\n" +
    "    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n" +
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n" + // one triangle covering the canvas
    "}\n";

  // ShaderToy's prelude for Image-tab code (compiler/target/shadertoy.py writes the same one).
  var PRELUDE =
    "#version 300 es\n" +
    "precision highp float;\n" +
    "precision highp int;\n" +
    "precision mediump sampler3D;\n" +
    "uniform vec3 iResolution;\n" +
    "uniform float iTime;\n" +
    "uniform float iTimeDelta;\n" +
    "uniform int iFrame;\n" +
    "uniform float iFrameRate;\n" +
    "uniform vec4 iMouse;\n" +
    "uniform vec4 iDate;\n" +
    "uniform float iChannelTime[4];\n" +
    "uniform vec3 iChannelResolution[4];\n" +
    "uniform float iSampleRate;\n" +
    "uniform sampler2D iChannel0;\n" +
    "uniform sampler2D iChannel1;\n" +
    "uniform sampler2D iChannel2;\n" +
    "uniform sampler2D iChannel3;\n";
  var PRELUDE_LINES = PRELUDE.split("\n").length - 1;
  var EPILOGUE =
    "\nout vec4 glintFragColor;\n" +
    "void main() {\n" +
    "    glintFragColor = vec4(0.0, 0.0, 0.0, 1.0);\n" +
    "    mainImage(glintFragColor, gl_FragCoord.xy);\n" +
    "}\n";
  var TIME_MAX = 20; // seconds on the scrub slider

  // The controls' few rules, added once (no stylesheet of its own to list and ship).
  var STYLE =
    ".glint-live canvas{display:block;width:100%;max-width:640px;height:auto;cursor:grab;" +
    "touch-action:none}" + // a drag sets iMouse rather than scrolling the page
    // the controls in columns as wide as a slider row needs: two on a wide page, one on a phone
    ".glint-live-controls{display:grid;grid-template-columns:repeat(auto-fill,minmax(22em,1fr));" +
    "gap:.25em 1.5em;align-items:center;max-width:920px;font-size:.7rem}" +
    ".glint-live-play{justify-self:start}" +
    // a row wraps on a narrow screen: the name above, the slider taking what is left
    ".glint-live-slider{display:flex;flex-wrap:wrap;align-items:center;gap:.25em .5em;" +
    "max-width:100%}" +
    ".glint-live-slider input[type=range]{flex:1 1 8em;min-width:6em}" +
    ".glint-live-name{font-family:var(--md-code-font-family,monospace);overflow-wrap:anywhere}" +
    ".glint-live-value{width:5.5em;font:inherit}" +
    ".glint-live-reset{border:0;background:none;cursor:pointer;font:inherit;padding:0 .2em}" +
    ".glint-live-errors{white-space:pre-wrap;color:#c62828}" +
    ".glint-live-choice{margin:0 0 .5em;font-size:.75rem}" +
    ".glint-compare-stage{position:relative;max-width:640px}" +
    ".glint-compare-b-view{position:absolute;left:0;top:0;width:100%;pointer-events:none}" +
    ".glint-compare-b-view .glint-live-controls,.glint-compare-b-view .glint-live-errors:empty" +
    "{display:none}" +
    ".glint-compare-difference{position:absolute;left:0;top:0;width:100%;height:auto;" +
    "image-rendering:pixelated}" +
    ".glint-compare-tools,.glint-compare-choices{font-size:.75rem;margin:.3em 0}" +
    ".glint-edit{max-width:640px;margin:.5em 0 1em}" +
    ".glint-edit-editor{border:1px solid var(--md-default-fg-color--lightest,#ccc);" +
    "font-size:.7rem;max-height:24em;overflow:auto}" +
    ".glint-edit-tools{display:flex;flex-wrap:wrap;gap:.5em;align-items:center;margin-top:.4em}" +
    ".glint-edit-tools .md-button{font-size:.7rem;padding:.2em .8em}" +
    ".glint-edit-status{font-size:.7rem}" +
    // CodeMirror's own theme is light: its gutter and active line, dark under Material's slate
    "[data-md-color-scheme=slate] .glint-edit .cm-gutters{background:#2b2d3a;color:#9a9cae;" +
    "border-color:#3c3f52}" +
    "[data-md-color-scheme=slate] .glint-edit .cm-activeLine{background:#ffffff0d}" +
    "[data-md-color-scheme=slate] .glint-edit .cm-activeLineGutter{background:#ffffff1a}" +
    "[data-md-color-scheme=slate] .glint-edit .cm-cursor{border-left-color:#e0e0e0}";

  var MAX_CONTEXTS = 8; // well under Chrome's ~16, which other pages' canvases share
  var instances = [];
  var observer = null;
  var clock = 0; // counts the times a canvas scrolled into view: the most recent is the highest

  function addStyle() {
    if (document.getElementById("glint-live-style")) return;
    var style = element("style");
    style.id = "glint-live-style";
    style.textContent = STYLE;
    document.head.appendChild(style);
  }

  function manifest(text) {
    var start = text.indexOf("/* glint-params\n");
    if (start < 0) return [];
    var body = text.slice(start + 16);
    try {
      return JSON.parse(body.slice(0, body.indexOf("*/")));
    } catch (error) {
      return []; // a broken manifest costs the sliders, not the picture
    }
  }

  // The pictures a scene binds to ShaderToy's channels ({"0": "img/live/pictures/x.png"}),
  // written after the shader by the site (compiler/site/channels.py).
  function channelManifest(text) {
    var start = text.indexOf("/* glint-channels\n");
    if (start < 0) return {};
    var body = text.slice(start + 18);
    try {
      return JSON.parse(body.slice(0, body.indexOf("*/")));
    } catch (error) {
      return {}; // a broken manifest costs the pictures (black, as unbound), not the canvas
    }
  }

  function element(tag, className, text) {
    var node = document.createElement(tag);
    if (className) node.className = className;
    if (text !== undefined) node.textContent = text; // text only: never HTML from a shader
    return node;
  }

  // A slider with the value typed in beside it and a reset to its first value. Over a range that
  // spans two decades or more (0.01 to 1000), the slider moves on a log scale, so that every
  // decade gets the same travel and the default can be found again.
  function slider(label, min, max, step, value, onInput, first) {
    var initial = first === undefined ? value : first; // what the reset returns to
    var log = min > 0 && max / min >= 100;
    var row = element("span", "glint-live-slider");
    var name = element("span", "glint-live-name", label);
    var input = element("input");
    input.type = "range";
    input.setAttribute("aria-label", label);
    if (log) {
      input.min = "0";
      input.max = "1000";
      input.step = "1";
      input.dataset.scale = "log";
    } else {
      input.min = String(min);
      input.max = String(max);
      input.step = String(step);
    }
    var typed = element("input", "glint-live-value");
    typed.type = "number";
    typed.min = String(min);
    typed.max = String(max);
    typed.step = "any";
    typed.setAttribute("aria-label", label + " value");
    var reset = element("button", "glint-live-reset", "\u21ba");
    reset.type = "button";
    reset.title = "reset " + label + " to " + initial;
    reset.setAttribute("aria-label", "reset " + label);

    function position(v) {
      if (!log) return String(v);
      return String(Math.round((1000 * Math.log(v / min)) / Math.log(max / min)));
    }
    function fromPosition() {
      if (!log) return Number(input.value);
      var v = min * Math.pow(max / min, Number(input.value) / 1000);
      return Number(v.toPrecision(4));
    }
    function show(v) {
      input.value = position(v);
      typed.value = String(Number(Number(v).toPrecision(6)));
    }
    function set(v, notify) {
      v = Math.min(max, Math.max(min, v));
      show(v);
      if (notify) onInput(v);
    }
    input.addEventListener("input", function () {
      var v = fromPosition();
      typed.value = String(v);
      onInput(v);
    });
    typed.addEventListener("change", function () {
      var v = Number(typed.value);
      if (typed.value === "" || !isFinite(v)) return show(fromPosition()); // keep what ran
      set(v, true);
    });
    reset.addEventListener("click", function () {
      set(initial, true);
    });
    show(value);
    row.appendChild(name);
    row.appendChild(input);
    row.appendChild(typed);
    row.appendChild(reset);
    return { row: row, input: input, shown: typed, set: set, reset: reset };
  }

  function Live(canvas) {
    this.canvas = canvas;
    this.time = Number(canvas.dataset.time || "0");
    this.frame = 0;
    this.mouse = [0, 0, 0, 0];
    this.playing = false;
    this.raf = 0;
    this.last = 0;
    this.gl = null;
    this.program = null;
    this.params = [];
    this.values = {};
    this.started = false;
    this.released = false; // the page changed: for good
    this.contextLost = false; // parked by the budget, or taken by the browser: comes back
    this.visible = false;
    this.seen = 0; // when it last scrolled into view (clock)
    this.source = null; // the shader as fetched
    this.patch = null; // an edit: { original, replacement } (setupEdit)
    this.text = null; // the shader that runs (the source, edited), kept for a lost context
    this.compiled = null; // the text of the program that runs
    this.lose = null; // the WEBGL_lose_context extension: park and restore
  }

  Live.prototype.start = function () {
    if (this.started) return;
    this.started = true;
    this.errors = element("pre", "glint-live-errors");
    this.errors.hidden = true;
    this.controls = element("div", "glint-live-controls");
    this.canvas.insertAdjacentElement("afterend", this.errors);
    this.errors.insertAdjacentElement("afterend", this.controls);
    this.bindMouse();
    var self = this;
    this.canvas.addEventListener("webglcontextlost", function (event) {
      event.preventDefault(); // without it the browser never gives the context back
      self.contextLost = true;
      self.program = null; // gone with the context
      if (self.playing) self.setPlaying(false);
      self.canvas.dataset.state = "lost";
    });
    this.canvas.addEventListener("webglcontextrestored", function () {
      self.contextLost = false;
      if (self.text !== null) self.compile(self.text);
      self.canvas.style.backgroundImage = ""; // the live frame is back in front
    });
    this.load();
  };

  // Give the context up, keeping the last frame as the canvas's background picture.
  Live.prototype.park = function () {
    if (!this.gl || this.contextLost || !this.lose) return;
    this.canvas.style.backgroundImage = "url(" + this.canvas.toDataURL() + ")";
    this.canvas.style.backgroundSize = "100% 100%";
    this.lose.loseContext(); // fires webglcontextlost
  };

  // Back in view: a context that was parked or taken comes back (webglcontextrestored).
  Live.prototype.unpark = function () {
    if (this.contextLost && this.lose && !this.released) this.lose.restoreContext();
  };

  // Fetch the shader that data-shader names and compile it, in place of any shader before it.
  Live.prototype.load = function () {
    var self = this;
    var path = this.canvas.dataset.shader;
    this.canvas.dataset.state = "loading";
    fetch(new URL(path, ROOT))
      .then(function (response) {
        if (!response.ok) throw new Error("cannot load the shader: HTTP " + response.status);
        return response.text();
      })
      .then(function (text) {
        // a later choice may have been made while this one loaded: only the last one counts
        if (self.released || self.canvas.dataset.shader !== path) return;
        self.source = text;
        self.text = self.patched(text);
        if (!self.contextLost) self.compile(self.text);
      })
      .catch(function (error) {
        self.fail(String(error.message || error));
      });
  };

  // The source with the edit in place of the code it replaces (unchanged without one).
  Live.prototype.patched = function (text) {
    var at = this.patch ? text.indexOf(this.patch.original) : -1;
    if (at < 0) return text;
    var end = at + this.patch.original.length;
    return text.slice(0, at) + this.patch.replacement + text.slice(end);
  };

  // An edit of the code `original` in the shader: compile it, keeping time, sliders and play.
  Live.prototype.edit = function (original, replacement) {
    this.patch = { original: original, replacement: replacement };
    if (this.source === null) return; // not loaded yet: load() applies it
    this.text = this.patched(this.source);
    if (this.contextLost || !this.started) return;
    var playing = this.playing;
    this.compile(this.text, true);
    if (playing && this.program) this.setPlaying(true);
  };

  // A selector's choice: another shader on the same canvas, at the same time and mouse.
  Live.prototype.choose = function (path) {
    this.canvas.dataset.shader = path;
    if (this.started && !this.released) this.load();
  };

  Live.prototype.fail = function (message) {
    this.errors.textContent = message;
    this.errors.hidden = false;
    this.canvas.dataset.state = "error";
  };

  // Compile `text` in place of the program before it; `keep` (an edit) keeps the sliders'
  // values, as does compiling the same text again (a context given back).
  Live.prototype.compile = function (text, keep) {
    var gl = this.canvas.getContext("webgl2", {
      alpha: false, // ShaderToy ignores alpha; a page must not blend the picture with its own
      antialias: false,
      preserveDrawingBuffer: true, // so that a paused frame can be read back (tests, saving)
    });
    if (!gl) return this.fail("This browser has no WebGL2.");
    this.gl = gl;
    this.lose = this.lose || gl.getExtension("WEBGL_lose_context");
    // the same shader again (a context given back): its sliders keep where the reader left them
    var kept = keep || text === this.compiled ? this.values : {};
    this.reset();
    var complete = /^\s*#version/.test(text);
    var source = complete ? text : PRELUDE + text + EPILOGUE;
    var offset = complete ? 0 : PRELUDE_LINES; // report Image-tab errors at the user's lines
    var vertex = this.shader(gl.VERTEX_SHADER, VERTEX, 0);
    var fragment = this.shader(gl.FRAGMENT_SHADER, source, offset);
    if (!vertex || !fragment) return;
    var program = gl.createProgram();
    gl.attachShader(program, vertex);
    gl.attachShader(program, fragment);
    gl.linkProgram(program);
    gl.deleteShader(vertex); // the program keeps what it needs
    gl.deleteShader(fragment);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      var linkLog = "link failed:\n" + gl.getProgramInfoLog(program);
      this.compiled = null;
      if (this.onCompile) this.onCompile([{ line: 0, message: linkLog }]);
      return this.fail(linkLog);
    }
    this.program = program;
    this.params = manifest(text);
    this.loadPictures(channelManifest(text));
    for (var i = 0; i < this.params.length; i++) {
      var name = this.params[i].name;
      this.values[name] = name in kept ? kept[name] : this.params[i].default;
    }
    this.compiled = text;
    if (this.onCompile) this.onCompile([]);
    this.buildControls();
    this.canvas.dataset.state = "ready";
    if (this.leader && this.leader.program) this.follow(this.leader);
    else this.draw();
  };

  // Bind each picture of the manifest to its channel as ShaderToy binds one: its bottom row at
  // v = 0, mipmapped, repeating. Until it arrives the channel samples black; it draws again then.
  Live.prototype.loadPictures = function (channels) {
    var gl = this.gl;
    var self = this;
    this.textures = [];
    this.sizes = new Float32Array(12).fill(1);
    Object.keys(channels).forEach(function (key) {
      var unit = Number(key);
      if (!(unit >= 0 && unit < 4)) return;
      var texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE,
                    new Uint8Array([0, 0, 0, 255]));
      self.textures[unit] = texture;
      var image = new Image();
      image.onload = function () {
        if (self.gl !== gl || self.contextLost || self.textures[unit] !== texture) return;
        gl.bindTexture(gl.TEXTURE_2D, texture);
        gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, true);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, image);
        gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
        gl.generateMipmap(gl.TEXTURE_2D);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
        self.sizes.set([image.width, image.height, 1], unit * 3);
        self.pictures = (self.pictures || 0) + 1;
        self.canvas.dataset.pictures = String(self.pictures);
        self.draw();
      };
      image.src = new URL(channels[key], ROOT).href;
    });
  };

  // Forget the shader before this one: its program, its parameters and their controls.
  Live.prototype.reset = function () {
    if (this.program && !this.contextLost) this.gl.deleteProgram(this.program);
    this.program = null;
    this.params = [];
    this.values = {};
    if (this.playing) this.setPlaying(false);
    this.controls.textContent = "";
    this.errors.textContent = "";
    this.errors.hidden = true;
  };

  Live.prototype.shader = function (kind, source, offset) {
    var gl = this.gl;
    var shader = gl.createShader(kind);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (gl.getShaderParameter(shader, gl.COMPILE_STATUS)) return shader;
    var log = String(gl.getShaderInfoLog(shader) || "compile failed");
    if (this.onCompile) this.onCompile(compileErrors(log));
    this.compiled = null;
    log = log.replace(/(ERROR: \d+:)(\d+)/g, function (all, head, line) {
      return head + Math.max(Number(line) - offset, 1);
    });
    this.fail(log);
    return null;
  };

  // A compiler's log as [{ line, message }], at the lines of the source it compiled (0: none).
  function compileErrors(log) {
    var errors = [];
    log.split("\n").forEach(function (entry) {
      var found = /^(?:ERROR|WARNING): \d+:(\d+): (.*)$/.exec(entry.trim());
      if (found && /^ERROR/.test(entry.trim())) {
        errors.push({ line: Number(found[1]), message: found[2] });
      } else if (!found && entry.trim() && !errors.length) {
        errors.push({ line: 0, message: entry.trim() });
      }
    });
    return errors.length ? errors : [{ line: 0, message: log }];
  }

  Live.prototype.buildControls = function () {
    var self = this;
    var play = element("button", "md-button glint-live-play", "Play");
    play.type = "button";
    play.addEventListener("click", function () {
      self.setPlaying(!self.playing);
    });
    this.playButton = play;
    this.controls.appendChild(play);
    this.timeSlider = slider("iTime", 0, TIME_MAX, 0.01, this.time, function (value) {
      self.time = value;
      if (!self.playing) self.draw();
    });
    this.controls.appendChild(this.timeSlider.row);
    this.params.forEach(function (param) {
      if (param.control === "color") return self.controls.appendChild(self.colorControl(param));
      if (param.control === "direction") {
        return self.directionControls(param).forEach(function (row) {
          self.controls.appendChild(row);
        });
      }
      var isInt = param.type === "int";
      var step = isInt ? 1 : (param.max - param.min) / 200;
      var value = self.values[param.name];
      var first = param.default; // a context given back keeps the value, the reset its default
      var control = slider(param.name, param.min, param.max, step, value, function (v) {
        self.values[param.name] = v;
        if (!self.playing) self.draw();
      }, first);
      control.input.dataset.param = param.name;
      self.controls.appendChild(control.row);
    });
  };

  // A linear RGB colour (a material's albedo) by a colour picker, which shows sRGB: the swatch
  // is the colour the reader sees, the uniform its linear value.
  Live.prototype.colorControl = function (param) {
    var self = this;
    var row = element("span", "glint-live-slider");
    var picker = element("input");
    picker.type = "color";
    picker.value = hexOfLinear(this.values[param.name]);
    picker.dataset.param = param.name;
    picker.setAttribute("aria-label", param.name);
    var reset = element("button", "glint-live-reset", "\u21ba");
    reset.type = "button";
    reset.title = "reset " + param.name;
    reset.setAttribute("aria-label", "reset " + param.name);
    function set(linear) {
      self.values[param.name] = linear;
      if (!self.playing) self.draw();
    }
    picker.addEventListener("input", function () {
      set(linearOfHex(picker.value));
    });
    reset.addEventListener("click", function () {
      picker.value = hexOfLinear(param.default);
      set(param.default.slice());
    });
    row.appendChild(element("span", "glint-live-name", param.name));
    row.appendChild(picker);
    row.appendChild(reset);
    return row;
  };

  // A unit vector toward a light by two sliders, azimuth around y and elevation above the
  // horizontal plane, in degrees (y is up in glint's scenes).
  Live.prototype.directionControls = function (param) {
    var self = this;
    var angles = anglesOf(this.values[param.name]);
    var first = anglesOf(param.default);
    function set() {
      self.values[param.name] = directionOf(angles[0], angles[1]);
      if (!self.playing) self.draw();
    }
    var azimuth = slider(param.name + " azimuth", -180, 180, 1, angles[0], function (v) {
      angles[0] = v;
      set();
    }, first[0]);
    var elevation = slider(param.name + " elevation", -90, 90, 1, angles[1], function (v) {
      angles[1] = v;
      set();
    }, first[1]);
    azimuth.input.dataset.param = param.name;
    azimuth.input.dataset.component = "azimuth";
    elevation.input.dataset.param = param.name;
    elevation.input.dataset.component = "elevation";
    return [azimuth.row, elevation.row];
  };

  function srgbOfLinear(c) {
    c = Math.min(1, Math.max(0, c));
    return c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
  }

  function linearOfSrgb(c) {
    return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
  }

  function hexOfLinear(rgb) {
    return "#" + rgb.map(function (c) {
      return ("0" + Math.round(255 * srgbOfLinear(c)).toString(16)).slice(-2);
    }).join("");
  }

  function linearOfHex(hex) {
    return [1, 3, 5].map(function (i) {
      return linearOfSrgb(parseInt(hex.slice(i, i + 2), 16) / 255);
    });
  }

  var DEGREE = Math.PI / 180;

  function anglesOf(v) {
    var length = Math.hypot(v[0], v[1], v[2]) || 1;
    var elevation = Math.asin(Math.max(-1, Math.min(1, v[1] / length))) / DEGREE;
    var azimuth = Math.atan2(v[2], v[0]) / DEGREE;
    return [Math.round(azimuth * 10) / 10, Math.round(elevation * 10) / 10];
  }

  function directionOf(azimuth, elevation) {
    var a = azimuth * DEGREE;
    var e = elevation * DEGREE;
    return [Math.cos(e) * Math.cos(a), Math.sin(e), Math.cos(e) * Math.sin(a)];
  }

  // ShaderToy's iMouse: xy the position while a button is down, zw where it went down; z and w
  // turn negative once it is released (pixels, origin at the bottom left).
  Live.prototype.bindMouse = function () {
    var self = this;
    var canvas = this.canvas;
    var down = false;
    function position(event) {
      var box = canvas.getBoundingClientRect();
      var x = ((event.clientX - box.left) * canvas.width) / box.width;
      var y = canvas.height - ((event.clientY - box.top) * canvas.height) / box.height;
      return [x, y];
    }
    canvas.addEventListener("pointerdown", function (event) {
      down = true;
      canvas.setPointerCapture(event.pointerId);
      var p = position(event);
      self.mouse = [p[0], p[1], p[0], p[1]];
      if (!self.playing) self.draw();
    });
    canvas.addEventListener("pointermove", function (event) {
      if (!down) return;
      var p = position(event);
      self.mouse[0] = p[0];
      self.mouse[1] = p[1];
      if (!self.playing) self.draw();
    });
    function release() {
      if (!down) return;
      down = false;
      self.mouse[2] = -Math.abs(self.mouse[2]);
      self.mouse[3] = -Math.abs(self.mouse[3]);
      if (!self.playing) self.draw();
    }
    canvas.addEventListener("pointerup", release);
    canvas.addEventListener("pointercancel", release);
  };

  Live.prototype.setPlaying = function (playing) {
    var self = this;
    this.playing = playing;
    this.playButton.textContent = playing ? "Pause" : "Play";
    cancelAnimationFrame(this.raf);
    if (!playing) return;
    this.last = performance.now();
    function tick(now) {
      if (!self.playing || self.released || self.contextLost) return;
      var delta = (now - self.last) / 1000;
      self.last = now;
      self.time = (self.time + delta) % TIME_MAX;
      self.timeSlider.set(self.time, false);
      self.draw(delta);
      self.raf = requestAnimationFrame(tick);
    }
    this.raf = requestAnimationFrame(tick);
  };

  Live.prototype.uniform = function (name) {
    return this.gl.getUniformLocation(this.program, name); // null for one the shader never reads
  };

  Live.prototype.draw = function (delta) {
    var gl = this.gl;
    if (!gl || !this.program || this.released || this.contextLost) return;
    var width = this.canvas.width;
    var height = this.canvas.height;
    var now = new Date();
    gl.viewport(0, 0, width, height);
    gl.useProgram(this.program);
    gl.uniform3f(this.uniform("iResolution"), width, height, 1);
    gl.uniform1f(this.uniform("iTime"), this.time);
    gl.uniform1f(this.uniform("iTimeDelta"), delta || 0);
    gl.uniform1i(this.uniform("iFrame"), this.frame);
    gl.uniform1f(this.uniform("iFrameRate"), 60);
    gl.uniform4fv(this.uniform("iMouse"), this.mouse);
    gl.uniform4f(
      this.uniform("iDate"),
      now.getFullYear(),
      now.getMonth(),
      now.getDate(),
      now.getHours() * 3600 + now.getMinutes() * 60 + now.getSeconds()
    );
    gl.uniform1f(this.uniform("iSampleRate"), 44100);
    var textures = this.textures || [];
    for (var unit = 0; unit < 4; unit++) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, textures[unit] || null); // none: samples black
      gl.uniform1i(this.uniform("iChannel" + unit), unit);
    }
    if (this.sizes) gl.uniform3fv(this.uniform("iChannelResolution"), this.sizes);
    for (var i = 0; i < this.params.length; i++) {
      var param = this.params[i];
      var value = this.values[param.name];
      if (param.type === "int") gl.uniform1i(this.uniform(param.name), Math.round(value));
      else if (param.type === "vec3") gl.uniform3fv(this.uniform(param.name), value);
      else gl.uniform1f(this.uniform(param.name), value);
    }
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    this.frame += 1;
    this.canvas.dataset.frames = String(this.frame);
    this.canvas.dataset.state = "drawn";
    if (this.follower) this.follower.follow(this);
    if (this.onDrawn) this.onDrawn();
  };

  // A comparison's B: the same time, mouse and shared parameters as A, drawn right after it.
  Live.prototype.follow = function (leader) {
    this.time = leader.time;
    this.mouse = leader.mouse.slice();
    for (var name in leader.values) {
      if (name in this.values) this.values[name] = leader.values[name];
    }
    this.draw();
  };

  Live.prototype.release = function () {
    this.released = true;
    this.playing = false;
    cancelAnimationFrame(this.raf);
    if (observer) observer.unobserve(this.canvas);
    if (this.gl && !this.contextLost && this.lose) this.lose.loseContext();
    this.gl = null;
    this.canvas.dataset.state = "released";
  };

  function alive(live) {
    return live.gl && !live.contextLost && !live.released;
  }

  // At most MAX_CONTEXTS alive: park those out of view, the longest out of view first.
  function keepWithinBudget() {
    var active = instances.filter(alive);
    var spare = active.filter(function (live) {
      return !live.visible;
    });
    spare.sort(function (a, b) {
      return a.seen - b.seen;
    });
    for (var i = 0; active.length - i > MAX_CONTEXTS && i < spare.length; i++) spare[i].park();
  }

  function releaseDetached() {
    instances = instances.filter(function (live) {
      if (live.canvas.isConnected) return true;
      live.release();
      return false;
    });
  }

  function setup() {
    releaseDetached(); // the page before this one, under instant navigation
    addStyle();
    if (!observer && "IntersectionObserver" in window) {
      observer = new IntersectionObserver(function (entries) {
        entries.forEach(function (entry) {
          var live = entry.target.glintLive;
          live.visible = entry.isIntersecting;
          if (!entry.isIntersecting) return;
          live.seen = ++clock;
          if (!live.started) live.start();
          else live.unpark();
        });
        keepWithinBudget();
      });
    }
    var canvases = document.querySelectorAll("canvas.glint-live-canvas[data-shader]");
    Array.prototype.forEach.call(canvases, function (canvas) {
      if (canvas.glintLive) return;
      var live = new Live(canvas);
      canvas.glintLive = live;
      var choice = canvas.parentElement.querySelector("select.glint-live-choice");
      if (choice) {
        choice.addEventListener("change", function () {
          live.choose(choice.value);
        });
      }
      instances.push(live);
      if (observer) observer.observe(canvas);
      else live.start();
    });
    Array.prototype.forEach.call(document.querySelectorAll(".glint-compare"), setupCompare);
    Array.prototype.forEach.call(document.querySelectorAll(".glint-edit"), setupEdit);
  }

  // The editor's script, loaded once and only for a page with an editor.
  var editorLoading = null;
  function loadEditor() {
    if (window.glintEditor) return Promise.resolve(window.glintEditor);
    if (!editorLoading) {
      editorLoading = new Promise(function (resolve, reject) {
        var script = element("script");
        script.src = new URL("assets/glint-editor.js", ROOT).href;
        script.onload = function () {
          if (window.glintEditor) resolve(window.glintEditor);
          else reject(new Error("the editor's script defines no editor"));
        };
        script.onerror = function () {
          editorLoading = null; // another page may try again
          reject(new Error("the editor's script did not load"));
        };
        document.head.appendChild(script);
      });
    }
    return editorLoading;
  }

  // A variant's code, editable (see the top of this file).
  function setupEdit(box) {
    if (box.glintEdit) return;
    var canvases = document.querySelectorAll("canvas.glint-live-canvas[data-shader]");
    var canvas = Array.prototype.find.call(canvases, function (c) {
      return c.dataset.shader === box.dataset.shader;
    });
    if (!canvas || !canvas.glintLive) return;
    box.glintEdit = true;
    var live = canvas.glintLive;
    var pre = box.querySelector(".glint-edit-code");
    var original = pre.textContent;
    var status = box.querySelector(".glint-edit-status");
    var editor = null;

    // Where the code starts in the shader (1-based line), to put an error at the editor's line.
    function firstLine() {
      var at = live.source === null ? -1 : live.source.indexOf(original);
      return at < 0 ? 1 : live.source.slice(0, at).split("\n").length;
    }
    live.onCompile = function (errors) {
      if (!editor || !live.patch) return;
      var first = firstLine();
      var lines = editor.text().split("\n").length;
      var mine = [];
      var elsewhere = [];
      errors.forEach(function (error) {
        var line = error.line - first + 1;
        if (error.line > 0 && line >= 1 && line <= lines) {
          mine.push({ line: line, message: error.message });
        } else {
          elsewhere.push(error.message + (error.line > 0 ? " (shader line " + error.line + ")" : ""));
        }
      });
      editor.showErrors(mine);
      box.dataset.state = errors.length ? "error" : "compiled";
      if (!errors.length) status.textContent = "compiled";
      else if (mine.length) status.textContent = "error at line " + mine[0].line + ": " + mine[0].message;
      else status.textContent = "error: " + elsewhere[0];
    };

    loadEditor()
      .then(function (api) {
        var host = element("div", "glint-edit-editor");
        editor = api.create(host, original, function (text) {
          live.edit(original, text);
        });
        pre.replaceWith(host);
        box.dataset.state = "ready";
      })
      .catch(function (error) {
        status.textContent = String(error.message || error) + ": the code is read-only";
      });

    box.querySelector(".glint-edit-reset").addEventListener("click", function () {
      if (editor) editor.setText(original);
    });
    box.querySelector(".glint-edit-copy").addEventListener("click", function () {
      fetch(new URL(box.dataset.shadertoy, ROOT))
        .then(function (response) {
          if (!response.ok) throw new Error("cannot load the shader: HTTP " + response.status);
          return response.text();
        })
        .then(function (text) {
          var at = text.indexOf(original);
          var code = editor ? editor.text() : original;
          if (at >= 0) text = text.slice(0, at) + code + text.slice(at + original.length);
          return navigator.clipboard.writeText(text).then(function () {
            status.textContent = "copied: the ShaderToy shader with your edit";
          });
        })
        .catch(function (error) {
          status.textContent = "copy failed: " + String(error.message || error);
        });
    });
  }

  // The A/B comparison (see the top of this file).
  function setupCompare(box) {
    if (box.glintCompare) return;
    box.glintCompare = true;
    var a = box.querySelector(".glint-compare-a-view canvas").glintLive;
    var b = box.querySelector(".glint-compare-b-view canvas").glintLive;
    var bView = box.querySelector(".glint-compare-b-view");
    var divider = box.querySelector(".glint-compare-divider");
    var showDifference = box.querySelector(".glint-compare-show-difference");
    var gain = box.querySelector(".glint-compare-gain");
    var difference = box.querySelector(".glint-compare-difference");
    a.follower = b;
    b.leader = a;
    function split() {
      bView.style.clipPath = "inset(0 0 0 " + divider.value + "%)";
    }
    function pixels(canvas) {
      var flat = document.createElement("canvas");
      flat.width = canvas.width;
      flat.height = canvas.height;
      var context = flat.getContext("2d");
      context.drawImage(canvas, 0, 0);
      return context.getImageData(0, 0, flat.width, flat.height);
    }
    function drawDifference() {
      difference.hidden = !showDifference.checked;
      bView.style.visibility = showDifference.checked ? "hidden" : "";
      if (!showDifference.checked || b.canvas.dataset.state !== "drawn") return;
      if (a.canvas.dataset.state !== "drawn") return;
      var pa = pixels(a.canvas);
      var pb = pixels(b.canvas);
      var out = difference.getContext("2d").createImageData(pa.width, pa.height);
      var k = Number(gain.value);
      for (var i = 0; i < pa.data.length; i += 4) {
        for (var c = 0; c < 3; c++) {
          out.data[i + c] = Math.min(255, Math.abs(pa.data[i + c] - pb.data[i + c]) * k);
        }
        out.data[i + 3] = 255;
      }
      difference.getContext("2d").putImageData(out, 0, 0);
      difference.dataset.state = "drawn";
    }
    b.onDrawn = drawDifference;
    divider.addEventListener("input", split);
    showDifference.addEventListener("change", drawDifference);
    gain.addEventListener("change", drawDifference);
    box.querySelector(".glint-compare-a").addEventListener("change", function (event) {
      a.choose(event.target.value);
    });
    box.querySelector(".glint-compare-b").addEventListener("change", function (event) {
      b.choose(event.target.value);
    });
    split();
  }

  // For tests and the curious: how many canvases hold a live WebGL context.
  window.glintLive = {
    contexts: function () {
      return instances.filter(alive).length;
    },
    budget: MAX_CONTEXTS,
  };

  window.addEventListener("pagehide", function () {
    instances.forEach(function (live) {
      live.release();
    });
    instances = [];
  });

  if (typeof document$ !== "undefined" && document$.subscribe) {
    document$.subscribe(setup); // Material: every page load, instant navigation included
  } else if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", setup);
  } else {
    setup();
  }
})();
