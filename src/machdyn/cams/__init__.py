"""Cams: follower motion programs, followers, profiles, the designer's checks and the cam machine's dynamics."""
