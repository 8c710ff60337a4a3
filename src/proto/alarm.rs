//! Alarms, alarm messages, operator messages and the alarm history.
