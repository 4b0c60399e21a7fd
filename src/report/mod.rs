//! Rendering results: text tables, JSON and CSV. Knows nothing of how the
//! numbers were computed.
