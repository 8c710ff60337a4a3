//! Program execution: numbers, names, blocks, modal data, timers.
