"""Lubricant films and the surfaces they separate: constants from the user's keys."""
