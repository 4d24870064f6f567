// the frame block
