// implemented in the foundation issue
