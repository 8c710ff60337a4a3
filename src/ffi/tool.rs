//! Tool numbers, tool life and counters.
