"""Linking and pruning: the units and every snippet they require in dependency order
(resolver), what mainImage never reaches dropped (reachability), the emitted text (emitter), the
Common/Image split, parameters as uniforms, and a snippet composed on its own with its
dependencies (standalone, snippet_evaluation: its probes and its CPU evaluation)."""
